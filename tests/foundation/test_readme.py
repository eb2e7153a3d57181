"""The README's plugin example runs as written."""

from __future__ import annotations

import re
from pathlib import Path

README = Path(__file__).resolve().parents[2] / "README.md"


def test_readme_plugin_example_runs(capsys):
    text = README.read_text()
    match = re.search(r"<!-- readme-plugin-example -->\n```python\n(.*?)```", text, re.S)
    assert match, "README lost its plugin example marker"
    exec(compile(match.group(1), "README.md", "exec"), {"__name__": "__main__"})
    printed = capsys.readouterr().out
    assert printed.strip() == "0.00390625 {'max_depth': 6}"  # 2 * 8 g / 2**12


def test_readme_sets_up_with_exactly_two_make_commands():
    text = README.read_text()
    assert "make run " in text and "make test " in text
    makefile = (README.parent / "Makefile").read_text()
    assert re.search(r"^run: ", makefile, re.M) and re.search(r"^test: ", makefile, re.M)
    assert "make test" in (README.parent / ".ci" / "run").read_text()
