"""``python -m tools.doccheck.repaste DUMP [DOC ...]``: paste fresh figures into shown outputs.

After a change that moves figures (a generator tweak re-runs every documented
benchmark), ``python -m tools.doccheck --mode all --dump DUMP`` keeps what each
command printed. This pastes those prints back: each line a document shows
under a command is replaced by the next printed line that reads the same with
figures masked (:func:`key`), so the document keeps its own choice of
lines (elisions, a table left out) and only its figures move. A shown line
with no such printed line is left as it is and listed: its words moved, and a
person rewrites it (and the prose around it, whose numbers this never touches).
In a block with such a line only table rows are pasted: prose the terminal
wrapped at other words can match the wrong printed line.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from sdt_framework.io import atomic_write_text

from .compare import BOXES, ELISION, PROGRESS, SPACES
from .extract import ROOT, Command, all_steps

#: a figure: a number standing alone or in a range (``0.22-0.34``), not part of a name
#: (``Motor-4``, ``ch1``, ``F1``, ``x4`` stay words here, where the checker masks some of
#: them: a pasted line must not come from another machine's table)
FIGURE = re.compile(r"(?<![\w.])(?<![A-Za-z]-)[-+−]?\d[\d,]*(?:\.\d+)?(?:[eE][-+]?\d+)?")


def key(line: str) -> str:
    """A line with its figures masked and table borders and spacing collapsed."""
    return SPACES.sub(" ", BOXES.sub(" | ", FIGURE.sub("#", line))).strip(" |")


def dumped(folder: Path, command: Command) -> list[str] | None:
    """What ``command`` printed in the dump (``__main__.dump``'s file), or None if not run."""
    path = folder / command.dump_name
    if not path.is_file():
        return None
    lines = path.read_text(encoding="utf-8").split("\n")
    return [line.rstrip() for line in lines[1:]]  # the first line repeats the command


def repaste(shown: tuple[str, ...], printed: list[str]) -> tuple[list[str], list[str]]:
    """(the shown lines with printed figures, the shown lines no printed line matches)."""
    out, unmatched, cursor = list(shown), [], 0
    keys = [key(line) for line in printed]
    for index, line in enumerate(shown):
        want = key(line)
        if line.strip() in ELISION or PROGRESS.search(line) or not want:
            continue
        match = next((j for j in range(cursor, len(keys)) if keys[j] == want), None)
        if match is None:
            unmatched.append(line)
            continue
        out[index], cursor = printed[match], match + 1
    if unmatched:  # prose wrapped elsewhere may have matched another line: keep table rows only
        out = [new if BOXES.search(old) else old for old, new in zip(shown, out, strict=True)]
    return out, unmatched


def main(argv: list[str] | None = None) -> int:
    """Rewrite the selected documents in place; print what could not be matched.

    A dump folder that does not exist or holds no dump, or a document that is not
    one of README.md and docs/*.md, is one ``error:`` line and exit 2, nothing
    written; each document is replaced whole or not at all (atomic write).
    """
    parser = argparse.ArgumentParser(prog="python -m tools.doccheck.repaste")
    parser.add_argument("dump", type=Path, help="the folder --dump wrote")
    parser.add_argument("docs", nargs="*", help="README.md, docs/x.md (default: all)")
    args = parser.parse_args(argv)
    steps_of = all_steps()
    unknown = sorted(set(args.docs) - set(steps_of))
    if unknown:
        return fail(f"not a checked document: {', '.join(unknown)} (README.md or docs/NAME.md)")
    names = {
        step.dump_name for steps in steps_of.values() for step in steps if isinstance(step, Command)
    }
    if not args.dump.is_dir() or not any((args.dump / name).is_file() for name in names):
        return fail(
            f"{args.dump} holds no dump: run python -m tools.doccheck --mode all --dump "
            f"{args.dump} first"
        )
    left = 0
    for doc in args.docs or steps_of:
        path = ROOT / doc
        text = path.read_text(encoding="utf-8")
        lines = text.split("\n")
        for step in steps_of[doc]:
            printed = dumped(args.dump, step) if isinstance(step, Command) else None
            if printed is None:
                continue
            new, unmatched = repaste(step.output, printed)
            lines[step.line : step.line + len(new)] = new  # step.line is 1-based: output next
            for line in unmatched:
                print(f"{step.id}: not printed: {line}")
            left += len(unmatched)
        if "\n".join(lines) != text:
            try:
                atomic_write_text(path, "\n".join(lines))
            except OSError as exc:
                return fail(f"cannot write {doc}: {exc.strerror}; make it writable and run again")
    print(f"{left} shown line(s) left as they were")
    return 0


def fail(message: str) -> int:
    """One ``error:`` line on stderr; the exit status of a user error."""
    print(f"error: {message}", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
