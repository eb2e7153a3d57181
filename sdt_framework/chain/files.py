"""Reading and writing signal arrays for the chain commands (.npy or .csv).

CSV layout: one acquisition per row (a single column or a single row is one
acquisition, read as 1-D); an optional non-numeric header line is skipped.
Writes are atomic (:mod:`sdt_framework.io`); CSV values use ``%.17g`` so a
float64 survives the round trip exactly.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from ..errors import SDTError
from ..io import atomic_path

__all__ = ["UNITS", "load_array", "save_array", "to_g"]

SUFFIXES = (".npy", ".csv")
UNITS = ("g", "mg", "lsb")


def _suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise SDTError(f"{path}: unsupported file type {suffix or '(none)'!r}; use .npy or .csv")
    return suffix


def load_array(path: str | os.PathLike[str]) -> NDArray[np.float64]:
    """Read a numeric array from ``path`` (.npy, or .csv with rows = acquisitions)."""
    path = Path(path)
    suffix = _suffix(path)
    if not path.is_file():
        raise SDTError(f"{path}: no such file")
    try:
        if suffix == ".npy":
            return np.asarray(np.load(path, allow_pickle=False))
        try:
            return np.loadtxt(path, delimiter=",", dtype=np.float64)
        except ValueError:
            return np.loadtxt(path, delimiter=",", dtype=np.float64, skiprows=1)
    except (ValueError, OSError) as exc:
        first = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise SDTError(f"{path}: cannot read numbers ({first})") from None


def save_array(path: str | os.PathLike[str], x: NDArray[np.float64]) -> Path:
    """Write ``x`` atomically to ``path`` (.npy, or .csv: a 1-D signal as one column)."""
    path = Path(path)
    suffix = _suffix(path)
    with atomic_path(path) as tmp, tmp.open("wb") as handle:
        if suffix == ".npy":
            np.save(handle, x, allow_pickle=False)
        else:
            np.savetxt(handle, x, delimiter=",", fmt="%.17g")
    return path


def to_g(x: NDArray[np.float64], unit: str, scale: float | None, label: str) -> NDArray[np.float64]:
    """Convert a recording from ``unit`` (g, mg, or raw LSB times ``scale`` g/LSB) to g."""
    if unit == "g":
        return x
    if unit == "mg":
        return x * 1e-3
    if unit == "lsb":
        if scale is None or not scale > 0:
            raise SDTError(f"{label}: --unit lsb needs --scale G_PER_LSB > 0, got {scale}")
        return x * scale
    raise SDTError(f"{label}: unknown unit {unit!r}; use one of {', '.join(UNITS)}")
