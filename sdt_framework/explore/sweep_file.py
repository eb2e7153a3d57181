"""Reading a sweep file: its ``[sweep]`` table validated into a :class:`Sweep`, its protocol.

Every error names the sweep file, the key and what to do, before any work.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from ..bench.config_paths import resolve_written, written_by_sdt
from ..errors import SpecFileError
from ..toml_files import read_toml, validate_file
from .sweep import Sweep

__all__ = ["load_sweep", "parse_sweep"]


def load_sweep(path: str | os.PathLike[str]) -> tuple[Sweep, dict[str, Any]]:
    """Read ``path``: the validated sweep and the raw ``[benchmark]`` table (protocol)."""
    path = Path(path)
    data = read_toml(
        path, what="sweep file", missing="sweep file not found; `sdt explore --example` prints one"
    )
    unknown = sorted(set(data) - {"sweep", "benchmark"})
    if unknown:
        raise SpecFileError(path, unknown[0], "unknown table; a sweep has [sweep] and [benchmark]")
    if "sweep" not in data:
        raise SpecFileError(path, "sweep", "missing; `sdt explore --example` shows the format")
    protocol = data.get("benchmark", {})
    if not isinstance(protocol, dict):
        raise SpecFileError(
            path, "benchmark", f"must be a table of options, got {type(protocol).__name__}"
        )
    if written_by_sdt(path):  # an exploration's own sweep.toml: paths relative to its folder
        protocol = resolve_written(protocol, path.parent)
    return parse_sweep(data["sweep"], path), dict(protocol)


def parse_sweep(table: dict[str, Any], where: str | os.PathLike[str] = "sweep") -> Sweep:
    """Validate a ``[sweep]`` table; errors name ``where`` and the key."""
    return validate_file(Sweep, table, where, prefix="sweep.", unknown="unknown key")
