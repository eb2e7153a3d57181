"""The manifest's rules against counting samples twice: no row, signal or recording id twice.

A manifest that lists the same samples twice would put them on both sides of
a train/test split, so each is refused naming the lines:

- two identical rows (labels compared without their surrounding spaces, as
  the reader reads them; the ``variable`` as written, since ``' a'`` and
  ``'a'`` may be two signals of one file);
- two rows reading one signal: the same file (after links) and the same
  signal *as its reader resolved it*, so a row naming a file's only signal
  and a row leaving ``variable`` empty, or ``' a'`` and ``'a'`` matching one
  signal, are caught too;
- two recordings whose ids ``machine/recording_id/channel`` meet (a ``/``
  inside a name).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from ..errors import SDTError
from ..signals.rules import SignalInfo
from ..signals.tokens import quote
from .manifest_table import ManifestRow

__all__ = ["refuse_identical", "refuse_shared_ids", "refuse_signal_twice"]


def refuse_identical(manifest: Path, header: list[str], rows: list[ManifestRow]) -> None:
    """Two rows alike in every column: refuse, naming both lines."""
    seen: dict[tuple[str, ...], str] = {}
    for row in rows:
        key = tuple(
            row.cells.get(name, "") if name == "variable" else row.cells.get(name, "").strip()
            for name in header
        )
        if key in seen:
            raise SDTError(
                f"manifest {manifest}: {seen[key]} and {row.where} are identical; remove one "
                f"(a repeated row would count the same samples twice)"
            )
        seen[key] = row.where


def refuse_signal_twice(
    manifest: Path, seen: dict[tuple[str, str], str], fields: dict[str, Any], info: SignalInfo
) -> None:
    """The row's signal (file after links, variable as resolved) read by an earlier row:
    refuse naming both lines; else remember it in ``seen``."""
    file = os.path.realpath(fields["file"])
    key = (file, "" if info.variable is None else str(info.variable))
    if key in seen:
        variable = f" (variable {quote(key[1])})" if key[1] else ""
        raise SDTError(
            f"manifest {manifest}: {seen[key]} and {fields['where']} both read {file}{variable}; "
            f"list each signal once (twice would count the same samples twice)"
        )
    seen[key] = fields["where"]


def refuse_shared_ids(
    manifest: Path, groups: dict[tuple[str, str, str], list[dict[str, Any]]]
) -> None:
    """Two groups whose ids collide ('/' inside a name): refuse, naming a line of each."""
    seen: dict[str, str] = {}
    for (machine, run, channel), rows in groups.items():
        rid = f"{machine}/{run}/{channel}"
        if rid in seen:
            raise SDTError(
                f"manifest {manifest}: {seen[rid]} and {rows[0]['where']} give the same "
                f"recording id {quote(rid, 60)}; avoid '/' in machine, recording_id and channel"
            )
        seen[rid] = rows[0]["where"]
