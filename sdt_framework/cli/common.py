"""Helpers shared by every ``sdt`` command: registry access, output, errors."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import typer
from rich.console import Console
from rich.table import Table

from ..registry import Registry, build_registry

__all__ = ["console", "err_console", "print_json", "registry", "table"]

console = Console()
err_console = Console(stderr=True)


def registry(ctx: typer.Context) -> Registry:
    """The registry for this invocation, built once, with plugin problems warned about."""
    root = ctx.find_root()
    root.ensure_object(dict)
    if "registry" not in root.obj:
        files: list[Path] = root.obj.get("sensor_files", [])
        reg = build_registry(sensor_files=files)
        for line in reg.problems():
            err_console.print(f"[yellow]warning:[/] {line}", highlight=False)
        root.obj["registry"] = reg
    return root.obj["registry"]


def print_json(data: Any) -> None:
    """Write ``data`` as indented JSON to stdout (for scripts; no colour)."""
    sys.stdout.write(json.dumps(data, indent=2, default=str) + "\n")


def table(title: str, columns: list[str], rows: list[list[Any]]) -> None:
    """Print a rich table."""
    out = Table(title=title, title_justify="left")
    for index, column in enumerate(columns):
        out.add_column(column, no_wrap=index == 0)  # names stay whole
    for row in rows:
        out.add_row(*["" if cell is None else str(cell) for cell in row])
    console.print(out)
