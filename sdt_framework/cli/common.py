"""Helpers shared by every ``sdt`` command: registry access, output, errors.

Both consoles print text as given: rich markup (``[bold]``, ``[/]``) and emoji
codes (``:x:``) are not interpreted, so a file called ``run[bold].npy`` or
``a:x:b.npy`` prints as itself and a message holding ``[/]`` cannot crash the
printer. Styled labels are built as :class:`rich.text.Text` (:func:`warn`,
:func:`print_error`), never by formatting a user string into markup. Control
characters in any printed string are shown as escapes, never sent to the
terminal (:mod:`.visible`).

A label from the user's data (a condition, recording or file name) can be of
any length; on the terminal each run of non-blank characters longer than
:data:`LABEL_LIMIT` is cut in the middle and a message is at most
:data:`MESSAGE_LIMIT` characters (:func:`shorten_labels`), so a 100 000-character
condition name is one readable line, not megabytes. Result files keep every
label whole.

Tables never cut a cell: when the console is narrower than a table (a pipe or
a file gets 80 columns), cells wrap (``overflow="fold"``) instead of being
truncated with an ellipsis, and a table whose columns cannot all fit even
folded is printed as plain ``column: value`` lines, so no number loses a digit
and no column disappears.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any

import typer
from rich.console import Console
from rich.measure import Measurement
from rich.table import Table
from rich.text import Text

from ..labels import middle_cut
from ..registry import Registry, build_registry
from .visible import SafeConsole, visible

__all__ = [
    "console",
    "err_console",
    "print_error",
    "print_json",
    "print_table",
    "registry",
    "shorten_labels",
    "table",
    "warn",
]

#: a run of non-blank characters longer than this is cut in the middle on the terminal
LABEL_LIMIT = 200
#: a printed message longer than this is cut in the middle
MESSAGE_LIMIT = 2000
_LONG_RUN = re.compile(rf"\S{{{LABEL_LIMIT + 1},}}")

console: Console = SafeConsole(markup=False, emoji=False)
err_console: Console = SafeConsole(stderr=True, markup=False, emoji=False)


def shorten_labels(message: str) -> str:
    """``message`` for the terminal: over-long labels and the message itself cut in the middle.

    Each run of non-blank characters longer than :data:`LABEL_LIMIT` keeps its
    first and last 60 characters (``healthyhhh…hhh (100,007 characters)``);
    a message still longer than :data:`MESSAGE_LIMIT` keeps its two ends.
    Shorter text is returned as it is.
    """
    if len(message) <= LABEL_LIMIT:
        return message
    message = _LONG_RUN.sub(lambda found: middle_cut(found[0], 60, count=True), message)
    if len(message) <= MESSAGE_LIMIT:
        return message
    return middle_cut(message, (MESSAGE_LIMIT - 40) // 2, count=True)


def print_error(message: str, label: str = "error:", style: str = "bold red") -> None:
    """Print ``label message`` on one line to stderr: as given, over-long labels shortened."""
    err_console.print(
        Text.assemble((label, style), " ", visible(shorten_labels(message))),
        highlight=False,
        soft_wrap=True,
    )


def warn(message: str, label: str = "warning:") -> None:
    """Print a yellow ``warning:`` line to stderr, ``message`` exactly as given."""
    print_error(message, label=label, style="yellow")


def registry(ctx: typer.Context) -> Registry:
    """The registry for this invocation, built once, with plugin problems warned about."""
    root = ctx.find_root()
    root.ensure_object(dict)
    if "registry" not in root.obj:
        files: list[Path] = root.obj.get("sensor_files", [])
        reg = build_registry(sensor_files=files)
        for line in reg.problems():
            warn(line)
        root.obj["registry"] = reg
    return root.obj["registry"]


def print_json(data: Any) -> None:
    """Write ``data`` as indented JSON to stdout (for scripts; no colour)."""
    sys.stdout.write(json.dumps(data, indent=2, default=str) + "\n")


def table(title: str, columns: list[str], rows: list[list[Any]]) -> None:
    """Print a rich table; cells and title are plain text (no markup, no emoji codes)."""
    out = Table(title=title, title_justify="left")
    for column in columns:
        out.add_column(column, overflow="fold")
    for row in rows:
        out.add_row(*["" if cell is None else str(cell) for cell in row])
    print_table(out)


def print_table(out: Table) -> None:
    """Print ``out`` so that no cell is cut: folded cells, or plain lines when too narrow.

    Every column folds (wraps inside the cell) instead of ending in an ellipsis.
    When the table's narrowest layout, every column as wide as its longest word,
    is wider than the console, rich would squeeze columns below their words and
    finally drop columns; the rows are printed as ``column: value`` lines instead.
    """
    for column in out.columns:
        column.overflow = "fold"
        column.no_wrap = False
    unbounded = console.options.update_width(1_000_000)
    if Measurement.get(console, unbounded, out).minimum <= console.width:
        console.print(out)
        return
    headers = [visible(str(column.header)) for column in out.columns]
    cells = [[" ".join(visible(str(cell)).split("\n")) for cell in column.cells]
             for column in out.columns]  # fmt: skip
    if out.title:
        console.print(str(out.title), soft_wrap=True, highlight=False)
    for row in zip(*cells, strict=True):
        pairs = [f"{h}: {v}" for h, v in zip(headers, row, strict=True) if v.strip()]
        console.print("  ".join(pairs), soft_wrap=True, highlight=False)
