"""Read the command blocks (and the files they need) out of the Markdown documents.

A fenced block whose lines start with ``$ `` holds commands, each followed by the
output the document shows for it. An HTML comment ``<!-- doccheck: ... -->`` on
the lines just above a fence annotates that block (``slow``, ``skip reason=...``,
``xfail reason=...``, ``link=FOLDER``, ``columns=N``, ``file=NAME``); a block
annotated ``file=NAME`` is not run but written to NAME in the sandbox when the
run reaches it, so a document can show the file a later command reads.
"""

from __future__ import annotations

import re
import shlex
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOTE = re.compile(r"<!--\s*doccheck:(.*?)-->")
FENCE = re.compile(r"^(```+|~~~+)")


@dataclass(frozen=True)
class Command:
    """One documented ``$`` line, the output shown under it and its block's notes."""

    doc: str
    line: int
    text: str
    output: tuple[str, ...]
    notes: dict[str, str] = field(default_factory=dict, compare=False, hash=False)

    @property
    def id(self) -> str:
        """``doc:line`` - stable enough to name a test and find the line."""
        return f"{self.doc}:{self.line}"

    @property
    def dump_name(self) -> str:
        """The file ``--dump`` writes this command's output to (and ``repaste`` reads)."""
        return self.id.replace("/", "_").replace(":", "_") + ".txt"


@dataclass(frozen=True)
class FileStep:
    """A fenced block the document names as a file (``file=NAME``): written, not run."""

    doc: str
    line: int
    name: str
    content: str
    notes: dict[str, str] = field(default_factory=dict, compare=False, hash=False)


def documents(root: Path = ROOT) -> list[Path]:
    """README.md and docs/*.md, in a fixed order."""
    return [root / "README.md", *sorted((root / "docs").glob("*.md"))]


def parse_notes(text: str) -> dict[str, str]:
    """``slow skip reason="needs X"`` -> {"slow": "", "skip": "", "reason": "needs X"}."""
    notes: dict[str, str] = {}
    for token in shlex.split(text):
        key, _, value = token.partition("=")
        notes[key] = value
    return notes


def split_commands(doc: str, start: int, body: list[str], notes: dict) -> list[Command]:
    """The ``$`` lines of one block (1-based ``start`` is its first body line)."""
    commands: list[Command] = []
    text, line, output = None, 0, []
    for offset, raw in enumerate(body):
        if raw.startswith("$ "):
            if text is not None:
                commands.append(Command(doc, line, text, tuple(output), notes))
            text, line, output = raw[2:], start + offset, []
        elif text is not None:
            output.append(raw)
    if text is not None:
        commands.append(Command(doc, line, text, tuple(output), notes))
    return commands


def steps(path: Path, root: Path = ROOT) -> list[Command | FileStep]:
    """The commands and named files of one document, in reading order."""
    doc = path.relative_to(root).as_posix()
    lines = path.read_text(encoding="utf-8").split("\n")
    found: list[Command | FileStep] = []
    pending: dict[str, str] = {}
    index = 0
    while index < len(lines):
        note = NOTE.search(lines[index])
        fence = FENCE.match(lines[index])
        if note:
            pending.update(parse_notes(note.group(1)))
        if not fence:
            index += 1
            continue
        end = index + 1
        while end < len(lines) and not lines[end].startswith(fence.group(1)):
            end += 1
        body = lines[index + 1 : end]
        if "file" in pending:
            content = "\n".join(body) + "\n"
            found.append(FileStep(doc, index + 1, pending["file"], content, pending))
        else:
            found.extend(split_commands(doc, index + 2, body, pending))
        pending = {}
        index = end + 1
    return found


def all_steps(root: Path = ROOT) -> dict[str, list[Command | FileStep]]:
    """Every document's steps, keyed by its path relative to the repository."""
    return {p.relative_to(root).as_posix(): steps(p, root) for p in documents(root)}
