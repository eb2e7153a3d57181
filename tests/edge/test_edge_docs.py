"""docs/edge.md: its Python blocks print what the page says, its `sdt budget` output is current."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from sdt_framework.cli.main import app

DOC = Path(__file__).resolve().parents[2] / "docs" / "edge.md"
TEXT = DOC.read_text(encoding="utf-8")


def test_python_blocks_print_what_the_page_says(capsys):
    blocks = re.findall(r"```python\n(.*?)```", TEXT, re.S)
    assert len(blocks) == 2
    for number, block in enumerate(blocks):
        exec(compile(block, f"{DOC.name}[python block {number}]", "exec"), {})
    out = capsys.readouterr().out.splitlines()
    assert out == ["96 ['DR3', 'DR4', 'DR5', 'DR6']", "61.696 ms", "[1. 1. 1.]"]


@pytest.mark.parametrize(
    "command", re.findall(r"^\$ sdt (budget.*)$", TEXT, re.M), ids=lambda c: c or "default"
)
def test_budget_output_on_the_page_is_what_the_command_prints(command):
    shown = TEXT.split(f"$ sdt {command}\n", 1)[1].split("```", 1)[0]
    result = runner_invoke(command.split()[1:])
    assert result == shown.rstrip("\n")


def runner_invoke(args: list[str]) -> str:
    result = CliRunner().invoke(app, ["budget", *args], env={"COLUMNS": "100"})
    assert result.exit_code == 0, result.output
    return result.stdout.rstrip("\n")


def test_readme_shows_the_same_budget_output():
    readme = (DOC.parents[1] / "README.md").read_text(encoding="utf-8")
    shown = readme.split("$ sdt budget\n", 1)[1].split("```", 1)[0]
    assert shown.rstrip("\n") == runner_invoke([])
