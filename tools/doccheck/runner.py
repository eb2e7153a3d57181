"""Run one document's blocks in order in one sandbox and judge each command.

Blocks run in reading order so a command finds the files an earlier one wrote.
``fast`` runs the blocks not annotated ``slow`` (the test suite's share);
``slow`` runs every block of a document that has a slow one (the ``make
doccheck`` share: earlier blocks are its set-up); ``all`` runs every block.
Skipped blocks are listed with their reason, never run.
"""

from __future__ import annotations

import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

from .compare import expectation, problems
from .extract import ROOT, Command, FileStep
from .sandbox import Sandbox
from .warm import WarmStart

BOX = re.compile(r"[\u2500-\u257f]")
FAST_TIMEOUT_S = 300.0
SLOW_TIMEOUT_S = 1800.0


@dataclass(frozen=True)
class Result:
    """The verdict on one command: passed, failed, skipped, xfailed or xpassed."""

    command: Command
    status: str
    detail: str = ""
    seconds: float = 0.0
    printed: str = ""
    cpu: float = 0.0


def has_slow(steps: list[Command | FileStep]) -> bool:
    """Whether any block of the document is annotated ``slow``."""
    return any("slow" in step.notes for step in steps)


def columns(command: Command) -> int:
    """Terminal width: the block's ``columns=N``, else the widest shown table (80 at least).

    A table narrower than the terminal prints the same at any width, and one
    wider is squeezed to exactly the width, so the widest table line shown is
    the width it was made at; plain lines (notes) are printed unwrapped.
    """
    if command.notes.get("columns"):
        return int(command.notes["columns"])
    return max([80, *(len(line) for line in command.output if BOX.search(line))])


def judge(command: Command, sandbox: Sandbox, timeout: float) -> Result:
    """Run one command (writing a ``cat FILE`` output first if FILE is missing)."""
    if command.text.startswith("cat ") and len(command.text.split()) == 2:
        name = command.text.split()[1]
        if not (sandbox.root / name).exists():
            sandbox.write(name, "\n".join(command.output) + "\n")
    expected = expectation(command.text, command.output)
    status, printed, seconds, cpu = sandbox.run(expected.command, columns(command), timeout)
    found = problems(expected, status, printed)
    detail = "\n".join(found) + ("\n  printed:\n" + _indent(printed) if found else "")
    if "xfail" in command.notes:
        verdict = "xfailed" if found else "xpassed"
        reason = command.notes.get("reason", "") + "\n" + detail
        return Result(command, verdict, reason, seconds, printed, cpu)
    return Result(command, "failed" if found else "passed", detail, seconds, printed, cpu)


def _indent(text: str, limit: int = 60) -> str:
    lines = text.splitlines()
    cut = lines[:limit] + ([f"... ({len(lines) - limit} more lines)"] if len(lines) > limit else [])
    return "\n".join(f"    | {line}" for line in cut)


def run_doc(
    steps: list[Command | FileStep],
    mode: str,
    cache: Path,
    root: Path = ROOT,
    warm: WarmStart | None = None,
):
    """Yield a Result per command of one document (``mode`` fast, slow or all), in order;
    its ``sdt`` commands start from ``warm``'s server when one is given (:mod:`.warm`)."""
    if mode == "slow" and not has_slow(steps):
        return
    with tempfile.TemporaryDirectory(prefix="doccheck-") as folder:
        sandbox = Sandbox(Path(folder), root, cache, warm)
        for step in steps:
            if "link" in step.notes:
                sandbox.link(step.notes["link"])
            if isinstance(step, FileStep):
                sandbox.write(step.name, step.content)
            elif "skip" in step.notes:
                yield Result(step, "skipped", step.notes.get("reason", "(no reason given)"))
            elif mode == "fast" and "slow" in step.notes:
                continue
            else:
                slow = mode == "slow" or "slow" in step.notes
                yield judge(step, sandbox, SLOW_TIMEOUT_S if slow else FAST_TIMEOUT_S)
