"""Every Python block of README.md runs as pasted, and every file the README shows loads.

Each ```python block is written to a file in an empty temporary folder and run
by a fresh interpreter there, alone: a block may not rely on names another block
defined (before: `x_ref`, `run_of_each_acquisition`, `labels` and `registry` were
used without being defined). The TOML files the README's commands need
(`my-mems.toml`, `node.toml`, the configuration example) are read as `sdt`
reads them.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from sdt_framework.bench.config import load_config

README = Path(__file__).resolve().parents[2] / "README.md"
TEXT = README.read_text(encoding="utf-8")
PYTHON = re.findall(r"^```python\n(.*?)^```", TEXT, re.S | re.M)


def _run(args: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {**os.environ, "SDT_CACHE_DIR": str(cwd / "cache"), "MPLBACKEND": "Agg"}
    return subprocess.run(args, cwd=cwd, capture_output=True, text=True, env=env, check=False)


def test_the_readme_has_its_python_blocks():
    assert len(PYTHON) >= 4


@pytest.mark.parametrize("index", range(len(PYTHON)))
def test_python_block_runs_as_pasted(index, tmp_path):
    (tmp_path / "snippet.py").write_text(PYTHON[index], encoding="utf-8")
    run = _run([sys.executable, "snippet.py"], tmp_path)
    assert run.returncode == 0, f"README python block {index + 1}:\n{run.stderr[-2000:]}"
    assert run.stdout.strip(), "every block shows its result"


def _toml(marker: str) -> str:
    match = re.search(rf"<!-- {marker} -->\n```toml\n(.*?)```", TEXT, re.S)
    assert match, f"README lost its {marker} block"
    return match.group(1)


def test_my_mems_toml_is_shown_and_loads_through_the_cli(tmp_path):
    """The README's command `sdt --sensor-file my-mems.toml ...` has its file on the page."""
    assert "sdt --sensor-file my-mems.toml" in TEXT
    (tmp_path / "my-mems.toml").write_text(_toml("readme-sensor-file"), encoding="utf-8")
    run = _run(
        [sys.executable, "-m", "sdt_framework", "--sensor-file", "my-mems.toml", "sensors",
         "show", "my-mems", "--json"],
        tmp_path,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    shown = json.loads(run.stdout)
    text = json.dumps(shown)
    assert "my-mems" in text and "1600" in text


def test_node_toml_is_shown_where_results_node_is_used(tmp_path):
    """`results/node` is made from the node.toml the README shows; it loads as a config."""
    at = TEXT.index("sdt compare results/node")
    assert TEXT.index("<!-- readme-node-toml -->") < at
    assert "sdt benchmark node.toml --out results/node" in TEXT[:at]
    path = tmp_path / "node.toml"
    path.write_text(_toml("readme-node-toml"), encoding="utf-8")
    config = load_config(path, {})
    assert config.sample == "node" and config.repeats == 3
    assert list(config.axes.values()) == ["x", "y", "z"]


def test_readme_links_the_paper_and_the_nln_emp_download():
    """The paper (its DOI, as its own supplementary-materials link gives it) and the data."""
    assert "https://doi.org/10.3390/machines14101113" in TEXT
    nln = "https://doi.org/10.4121/2b61183e-c14f-4131-829b-cc4822c369d0"
    at = TEXT.index("- **NLN-EMP**")
    assert nln in TEXT[:1500] and nln in TEXT[at : at + 400]
