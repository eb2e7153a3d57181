"""Reading and writing signal arrays for the chain commands (.npy or .csv).

A CSV is read by the same rule as a manifest's CSV signal
(:func:`sdt_framework.data.csv_signal.read_csv_signal`): a header line and a
time column are detected (the time column is dropped and a note says so), and
the longer axis is time, so an ordinary ``time,acc`` file is one acquisition
and a ``numpy.savetxt`` of an (acquisitions, samples) array is that many rows.
A single series is returned 1-D. An NPY array is taken as stored (1-D, or
rows = acquisitions). Writes are atomic (:mod:`sdt_framework.io`); CSV values
use ``%.17g`` so a float64 survives the round trip exactly. Every failure is a
one-line :class:`~sdt_framework.errors.SDTError` naming the path.

Before reading, :func:`check_signal_size` and :func:`check_pair_size` size the
job from the files' headers (:mod:`sdt_framework.data.signal_sizes`) and
refuse one that cannot fit in the memory available.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from ..errors import SDTError
from ..inputs import require_regular_file
from ..io import atomic_path

__all__ = [
    "SUFFIXES",
    "UNITS",
    "LoadedSignal",
    "check_pair_size",
    "check_signal_size",
    "load_signal",
    "save_array",
    "to_g",
]

SUFFIXES = (".npy", ".csv")
UNITS = ("g", "mg", "lsb")


class LoadedSignal(NamedTuple):
    """A signal read from a file, and a note when a CSV time column was dropped."""

    data: NDArray[np.float64]
    note: str | None


def _suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise SDTError(f"{path}: unsupported file type {suffix or '(none)'!r}; use .npy or .csv")
    return suffix


def load_signal(path: str | os.PathLike[str]) -> LoadedSignal:
    """Read a numeric array from ``path`` (.npy, or .csv by the shared CSV rule)."""
    from ..data.csv_signal import read_csv_signal  # the one CSV rule (imported on use)
    from ..data.tokens import brief

    path = Path(path)
    if path.is_dir():
        raise SDTError(f"{path}: is a folder; give the signal file")
    suffix = _suffix(path)
    require_regular_file(path, "signal file")
    if not path.is_file():
        raise SDTError(f"{path}: no such file; check the path")
    if suffix == ".csv":
        parsed = read_csv_signal(path)
        data = parsed.data[0] if parsed.data.shape[0] == 1 else parsed.data
        return LoadedSignal(data, parsed.note)
    try:
        return LoadedSignal(np.asarray(np.load(path, allow_pickle=False)), None)
    except OSError as exc:
        raise SDTError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, EOFError) as exc:
        raise SDTError(f"{path}: not a readable .npy file ({brief(exc)})") from None


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


def check_signal_size(path: Path, bytes_per_sample: int, advice: str) -> None:
    """Refuse the signal file ``path`` before reading it if its samples (from its header)
    at ``bytes_per_sample`` each need more memory than is available."""
    from ..data.signal_sizes import CSV_PARSE_BYTES_PER_SAMPLE, file_samples
    from .guards import check_memory

    samples = file_samples(path)
    if samples is not None:
        if path.suffix.lower() == ".csv":
            bytes_per_sample += CSV_PARSE_BYTES_PER_SAMPLE
        check_memory(path, f"{samples:,} samples", samples * bytes_per_sample, advice)


def check_pair_size(pair: Path) -> None:
    """Refuse a paired recording (TOML pair or IDE file) that ``sdt twin check`` cannot hold.

    A TOML pair is sized from its two files' headers, an IDE file from its
    bytes; a pair that cannot be read this way is left to the loader's message.
    """
    from ..data.signal_sizes import TWIN_BYTES_PER_IDE_BYTE, TWIN_BYTES_PER_SAMPLE, file_samples
    from .guards import check_memory

    advice = "cut the recordings to a shorter stretch (a few minutes hold every band)"
    try:
        if pair.suffix.lower() != ".toml":
            size = pair.stat().st_size if pair.is_file() else 0
            check_memory(
                pair, f"{size:,} bytes of recording", size * TWIN_BYTES_PER_IDE_BYTE, advice
            )
            return
        import tomllib

        tables = tomllib.loads(pair.read_text(encoding="utf-8"))
        sides = [tables.get(side) for side in ("reference", "device")]
        files = [(pair.parent / s["file"], s.get("variable")) for s in sides]
    except (OSError, UnicodeError, ValueError, TypeError, KeyError):
        return  # the loader says what is wrong with the file
    counts = [file_samples(file, variable) for file, variable in files]
    if None not in counts:
        samples = sum(c for c in counts if c is not None)
        check_memory(pair, f"{samples:,} samples", samples * TWIN_BYTES_PER_SAMPLE, advice)
