"""Every fast command shown in README.md and docs/*.md runs as written and prints what is shown.

One test per ``$`` line; a document's commands run once, in order, in one
sandbox (``tools.doccheck``), and each test reads its own verdict. Blocks
annotated ``slow`` run in ``make doccheck`` (CI, after ``make test``); blocks
annotated ``skip`` name why they cannot run here and are listed there.
"""

from __future__ import annotations

import contextlib
import os
import sys
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from tools.doccheck.extract import Command, all_steps
from tools.doccheck.runner import Result, run_doc
from tools.doccheck.warm import warm_or_cold

STEPS = all_steps()
FAST = [
    step
    for steps in STEPS.values()
    for step in steps
    if isinstance(step, Command) and not {"slow", "skip"} & step.notes.keys()
]


@pytest.fixture(scope="session")
def verdicts(request, tmp_path_factory) -> dict[str, Future]:
    """Each selected document's fast commands, run once, two documents at a time.

    Documents are independent (one sandbox each), so on the 2-core machine two
    run side by side; each test waits for its own document's verdicts. Under
    pytest-xdist (``make test``: one worker per core) the other workers keep
    the other cores busy, so this worker runs its documents one at a time.
    Their ``sdt`` commands start warm, as ``python -m tools.doccheck`` runs them
    (``tools/doccheck/warm.py``).
    """
    cache = tmp_path_factory.mktemp("doccheck-cache")
    stack = contextlib.ExitStack()
    warm = warm_or_cold(stack)  # as python -m tools.doccheck: cold, with a note, off Linux
    # other tests name a parameter "command" too (a string there): keep this file's only
    params = [getattr(item, "callspec", None) for item in request.session.items]
    docs = {
        p.params["command"].doc
        for p in params
        if p and isinstance(p.params.get("command"), Command)
    }
    workers = int(os.environ.get("PYTEST_XDIST_WORKER_COUNT", "1"))
    pool = ThreadPoolExecutor(max_workers=max(1, 2 // workers))
    request.addfinalizer(stack.close)
    request.addfinalizer(pool.shutdown)  # finalizers run last first: the pool ends, then warm

    def run(doc: str) -> dict[str, Result]:
        return {r.command.id: r for r in run_doc(STEPS[doc], "fast", cache, warm=warm)}

    return {doc: pool.submit(run, doc) for doc in sorted(docs)}


def test_documents_hold_commands():
    """The extractor still finds the documented commands (a format change would hide them)."""
    assert len(FAST) >= 40
    assert any(c.text.startswith("sdt twin check") for c in FAST)


@pytest.mark.parametrize("command", FAST, ids=lambda c: f"{c.id} {c.text[:60]}")
def test_documented_command(command: Command, verdicts):
    result = verdicts[command.doc].result()[command.id]
    if result.status == "xfailed":
        pytest.xfail(command.notes.get("reason", ""))
    assert result.status in {"passed", "xpassed"}, f"$ {command.text}\n{result.detail}"
