"""Judge one command's output against the lines its document shows.

Numbers are masked (``0.4636`` and ``0.4522`` both read ``#``), box-drawing
characters and runs of spaces are collapsed, so noise in figures and the column
widths it causes pass; a documented line that the run does not print at all is
missing. A small share of missing lines (wrapping moved by a longer number) is
tolerated in outputs of 10 lines or more; an error line, a changed word or a
lost row of a short table is not.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

# a number, unless it ends a name (adxl345, ch1, SF12: two letters before it)
NUMBER = re.compile(r"(?<![A-Za-z_][A-Za-z_])(?<![\d.])[-+−]?\d[\d,]*(?:\.\d+)?(?:[eE][-+]?\d+)?")
BOXES = re.compile(r"[\u2500-\u257f|]+")
SPACES = re.compile(r"\s+")
PROGRESS = re.compile(r"━+\s+\d+/\d+")
ELISION = {"...", "…", ""}
ECHO_STATUS = re.compile(r';\s*echo\s+"?(?:exit\s+)?\$\?"?\s*$')
MISSING_SHARE = 0.2
MISSING_FROM = 10  # shorter outputs must be printed whole
TRACEBACK = "Traceback (most recent call last)"


@dataclass(frozen=True)
class Expectation:
    """What to run and what must come of it."""

    command: str
    status: int
    lines: tuple[str, ...]


def normalise(line: str) -> str:
    """A line with numbers masked and table borders and spacing collapsed."""
    line = NUMBER.sub("#", line)
    line = BOXES.sub(" | ", line)
    return SPACES.sub(" ", line).strip(" |")


def expectation(command: str, output: tuple[str, ...]) -> Expectation:
    """Split ``; echo $?`` off a command and read the exit status the document shows.

    With ``echo "exit $?"`` (or ``echo $?``) the last shown line is the status;
    otherwise a shown ``error:`` line means the documented user error (status 2),
    and anything else success.
    """
    lines = tuple(output)
    match = ECHO_STATUS.search(command)
    if match and lines and NUMBER.search(lines[-1]):
        status = int(NUMBER.search(lines[-1]).group())
        return Expectation(command[: match.start()], status, lines[:-1])
    failed = any(line.startswith("error:") for line in lines)
    return Expectation(command, 2 if failed else 0, lines)


def required(lines: tuple[str, ...]) -> list[str]:
    """The shown lines a run must print: not elisions, not progress bars."""
    keep = [line for line in lines if line.strip() not in ELISION and not PROGRESS.search(line)]
    return [normalise(line) for line in keep if normalise(line)]


def printed_line(line: str, got: list[str]) -> bool:
    """Whether a documented line was printed: as a line, or for prose wrapped elsewhere.

    Text outside tables is re-wrapped by the terminal's width (a longer number
    moves a word to the next line), so a prose line also counts when it reads
    inside the printed text joined into one line.
    """
    if line in got:
        return True
    return "|" not in line and line in " ".join(got)


def problems(expected: Expectation, status: int, printed: str) -> list[str]:
    """Everything wrong with one run, empty when it agrees with its document."""
    found: list[str] = []
    if status != expected.status:
        found.append(f"exit status {status}, documented {expected.status}")
    if TRACEBACK in printed:
        found.append("a Python traceback was printed")
    wanted = required(expected.lines)
    got = [normalise(line) for line in printed.splitlines()]
    missing = [line for line in wanted if not printed_line(line, got)]
    allowed = int(MISSING_SHARE * len(wanted)) if len(wanted) >= MISSING_FROM else 0
    if len(missing) > allowed:
        shown = "\n".join(f"    - {line}" for line in missing)
        found.append(f"{len(missing)} of {len(wanted)} documented lines not printed:\n{shown}")
    return found
