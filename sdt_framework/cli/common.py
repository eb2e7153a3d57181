"""Helpers shared by every ``sdt`` command: registry access, output, errors.

Both consoles print text as given: rich markup (``[bold]``, ``[/]``) and emoji
codes (``:x:``) are not interpreted, so a file called ``run[bold].npy`` or
``a:x:b.npy`` prints as itself and a message holding ``[/]`` cannot crash the
printer. Styled labels are built as :class:`rich.text.Text` (:func:`warn`,
:func:`print_error`), never by formatting a user string into markup.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import typer
from rich.console import Console
from rich.table import Table
from rich.text import Text

from ..registry import Registry, build_registry

__all__ = ["console", "err_console", "print_error", "print_json", "registry", "table", "warn"]

console = Console(markup=False, emoji=False)
err_console = Console(stderr=True, markup=False, emoji=False)


def print_error(message: str, label: str = "error:", style: str = "bold red") -> None:
    """Print ``label message`` on one line to stderr, ``message`` exactly as given."""
    err_console.print(Text.assemble((label, style), " ", message), highlight=False, soft_wrap=True)


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
    for index, column in enumerate(columns):
        out.add_column(column, no_wrap=index == 0)  # names stay whole
    for row in rows:
        out.add_row(*["" if cell is None else str(cell) for cell in row])
    console.print(out)
