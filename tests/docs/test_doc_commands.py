"""Every fast command shown in README.md and docs/*.md runs as written and prints what is shown.

One test per ``$`` line; a document's commands run once, in order, in one
sandbox (``tools.doccheck``), and each test reads its own verdict. Blocks
annotated ``slow`` run in ``make doccheck`` (CI, after ``make test``); blocks
annotated ``skip`` name why they cannot run here and are listed there.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tools.doccheck.extract import Command, all_steps
from tools.doccheck.runner import Result, run_doc

STEPS = all_steps()
FAST = [
    step
    for steps in STEPS.values()
    for step in steps
    if isinstance(step, Command) and not {"slow", "skip"} & step.notes.keys()
]


@pytest.fixture(scope="session")
def verdicts(tmp_path_factory) -> dict[str, dict[str, Result]]:
    """Lazily run each document's fast commands once; keyed by document, then command id."""
    cache = tmp_path_factory.mktemp("doccheck-cache")
    done: dict[str, dict[str, Result]] = {}

    class Lazy(dict):
        def __missing__(self, doc: str) -> dict[str, Result]:
            results = {r.command.id: r for r in run_doc(STEPS[doc], "fast", cache)}
            done[doc] = results
            self[doc] = results
            return results

    return Lazy()


def test_documents_hold_commands():
    """The extractor still finds the documented commands (a format change would hide them)."""
    assert len(FAST) >= 40
    assert any(c.text.startswith("sdt twin check") for c in FAST)


@pytest.mark.parametrize("command", FAST, ids=lambda c: f"{c.id} {c.text[:60]}")
def test_documented_command(command: Command, verdicts):
    result = verdicts[command.doc][command.id]
    if result.status == "xfailed":
        pytest.xfail(command.notes.get("reason", ""))
    assert result.status in {"passed", "xpassed"}, f"$ {command.text}\n{result.detail}"
