"""Every `--help` example runs as written from the repository root.

Each file an example reads either ships in the repository (tests/data/endaq/...,
examples/...) or is made by an earlier example of the same help text (its
--out, --plot or `>`), so a new user can paste the examples in order; a dataset
that must be downloaded is said so on the example's line. No help text or
message cites "SPEC section N" of a document that does not ship, and no option
help loses a bracketed word to rich markup ("( axes, nodes)").
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from sdt_framework.cli.main import app

ROOT = Path(__file__).resolve().parents[2]
OUTPUTS = {"--out", "--plot"}
SUFFIXES = {".npy", ".csv", ".toml", ".ide", ".parquet", ".png", ".json", ".html", ".md"}


def _commands() -> dict[str, object]:
    """Every command and group of ``sdt``, by the words a user types."""
    found: dict[str, object] = {}

    def walk(command, path: tuple[str, ...]) -> None:
        found[" ".join(path)] = command
        if hasattr(command, "list_commands"):
            for name in command.list_commands(None):
                walk(command.get_command(None, name), (*path, name))

    walk(typer.main.get_command(app), ("sdt",))
    return found


COMMANDS = _commands()


def _examples(help_text: str) -> list[str]:
    """The example lines of a help text, as a user would paste them."""
    if "Example" not in help_text:
        return []
    after = re.split(r"Examples?:", help_text, maxsplit=1)[1].replace("\\\n", " ")
    lines = [line.strip() for line in after.splitlines()]
    return [line.replace("\\[", "[") for line in lines if re.match(r"(\w+=\S+ )*sdt ", line)]


def _is_path(token: str) -> bool:
    return "/" in token or Path(token).suffix.lower() in SUFFIXES


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_help_examples_name_files_that_exist_or_are_made_first(name):
    made: list[str] = []
    for line in _examples(COMMANDS[name].help or ""):
        tokens = shlex.split(line, comments=True)
        outputs = {tokens[i + 1] for i, t in enumerate(tokens[:-1]) if t in OUTPUTS or t == ">"}
        for i, token in enumerate(tokens):
            if token.startswith("-") or token in outputs or not _is_path(token):
                continue
            if i and tokens[i - 1] in {"--sensors", "--transfer", "--sensor", "--pattern"}:
                continue  # names and path templates, not files
            if "NLN-EMP" in token:
                assert "needs NLN-EMP downloaded" in line, (name, line)
                continue
            exists = any(ROOT.glob(token)) if "*" in token else (ROOT / token).exists()
            earlier = any(token == m or token.startswith(m.rstrip("/") + "/") for m in made)
            assert exists or earlier, f"{name} --help: {token!r} neither ships nor is made first"
        made += sorted(outputs)


def test_every_command_has_examples():
    leaves = [n for n, c in COMMANDS.items() if not hasattr(c, "list_commands")]
    missing = [n for n in leaves if not _examples(COMMANDS[n].help or "")]
    assert not missing


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_help_cites_no_spec_section_and_loses_no_bracketed_word(name):
    words = name.split()[1:]
    result = CliRunner().invoke(app, [*words, "--help"], env={"COLUMNS": "250"})
    assert result.exit_code == 0, result.output
    assert "SPEC section" not in result.output
    for param in COMMANDS[name].params:
        text = getattr(param, "help", None) or ""
        assert not re.search(r"(?<!\\)\[[a-z]", text), (name, param.name, text)


def test_errors_and_sources_cite_no_spec_section(tmp_path, sdt_in_process, monkeypatch):
    np.save(tmp_path / "x.npy", np.zeros(300))
    monkeypatch.chdir(tmp_path)  # the commands run in this process, from tmp_path
    runs = [
        ["features", "extract", "x.npy", "--fs", "15", "--out", "f.parquet"],
        ["sensors", "show", "native-reference"],
        ["sensors", "show", "adxl1002"],
    ]
    for index, args in enumerate(runs):
        run = sdt_in_process(*args, env={"COLUMNS": "200"})
        assert "SPEC section" not in run.stdout + run.stderr, args
        assert "Traceback" not in run.stderr, run.stderr
        if index == 0:  # the empty-band error points at a document that ships
            assert run.returncode == 2 and "(docs/features.md, Windows)" in run.stderr
