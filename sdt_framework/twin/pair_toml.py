"""A paired recording that is not an IDE file, described by a small TOML file.

Two tables, ``[reference]`` and ``[device]``, each naming one signal::

    [reference]
    file = "piezo.csv"            # CSV, NPY or MAT; relative to this TOML's folder
    columns = ["ax", "ay", "az"]  # CSV header names, one per axis (CSV only)
    time_column = "t"             # timestamps in s (CSV); or rate_hz = 20000
    axes = ["x", "y", "z"]        # which axis each column (or array row) measures
    units = "m/s^2"               # g, mg or m/s^2 (converted to g)
    part = "832M1"                # optional, printed

    [device]
    file = "adxl345.npy"          # rows (or columns) = axes, the longer side is time
    rate_hz = 3134.27
    axes = ["x", "y", "z"]
    start_s = 0.0                 # time of the first sample on the reference's clock

A signal with a time column gets the same treatment as an IDE channel: its
rate measured from the timestamps, resampled onto an even grid with a note
when they stray (:mod:`sdt_framework.data.timebase`). A MAT file names its
array with ``variable``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, FiniteFloat, model_validator

from ..data.csv_signal import read_csv_signal
from ..data.recording import DataFileError
from ..data.signal_files import read_signal
from ..data.timebase import on_even_grid
from ..errors import SDTError
from ..toml_files import read_toml, validate_file
from .signals import Pair, Signal, chosen_axes, digest

__all__ = ["PairSignal", "is_pair_toml", "load_toml_pair"]

#: a part name is printed up to this many characters
PART_CHARACTERS = 60
#: multiply by this to get g (standard gravity for m/s^2, ISO 80000-3)
TO_G = {"g": 1.0, "mg": 1e-3, "m/s^2": 1 / 9.80665}


class PairSignal(BaseModel):
    """One side of a TOML pair: where its samples are, what axes, at what rate, in what unit."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    file: str = Field(min_length=1)
    axes: list[Literal["x", "y", "z"]] = Field(min_length=1, max_length=3)
    columns: list[str] | None = None
    variable: str | None = None
    time_column: str | None = None
    rate_hz: FiniteFloat | None = Field(None, gt=0)
    start_s: FiniteFloat = 0.0
    units: Literal["g", "mg", "m/s^2"] = "g"
    part: str | None = None

    @model_validator(mode="after")
    def _consistent(self) -> PairSignal:
        if (self.rate_hz is None) == (self.time_column is None):
            raise ValueError("give exactly one of rate_hz or time_column")
        if len(set(self.axes)) != len(self.axes):
            raise ValueError(f"axes {self.axes} name an axis twice")
        if self.columns is not None and len(self.columns) != len(self.axes):
            raise ValueError(f"{len(self.columns)} columns for {len(self.axes)} axes")
        columns = self.columns or []
        twice = [c for c in dict.fromkeys(columns) if columns.count(c) > 1]
        if twice:
            raise ValueError(f"columns name {_short(twice[0])} twice; name one column per axis")
        if self.time_column is not None and self.time_column in columns:
            raise ValueError(
                f"time_column {_short(self.time_column)} is also among columns; the time is "
                f"not an axis"
            )
        csv = self.file.lower().endswith(".csv")
        if not csv and (self.columns or self.time_column):
            raise ValueError("columns and time_column are for CSV files (give rate_hz)")
        return self


class _PairFile(BaseModel):
    model_config = ConfigDict(extra="forbid")

    reference: PairSignal
    device: PairSignal


def _cut(text: str, limit: int = PART_CHARACTERS) -> str:
    """``text`` cut to ``limit`` characters (a 100 kB name is not echoed whole)."""
    return text if len(text) <= limit else text[: limit - 1] + "\u2026"


def _short(text: str) -> str:
    """``text`` cut and quoted, for a message."""
    return repr(_cut(text))


def is_pair_toml(path: str | Path) -> bool:
    """Whether ``path`` names a TOML pair description (by its suffix)."""
    return Path(path).suffix.lower() == ".toml"


def _samples(folder: Path, side: str, spec: PairSignal) -> tuple[np.ndarray, np.ndarray | None]:
    """(values (axes, n) in the file's unit, timestamps or None)."""
    file = folder / spec.file
    if not file.is_file():
        raise SDTError(f"{file}: [{side}] file not found; paths are relative to the pair file")
    times = None
    if spec.columns is not None:  # the signal columns and the time column in one read
        extra = [] if spec.time_column is None else [spec.time_column]
        table = read_csv_signal(file, [*spec.columns, *extra]).data
        values = table[: len(spec.columns)]
        if extra:
            times = table[-1]
    else:
        values = read_signal(file, spec.variable)
        if spec.time_column is not None:
            times = read_csv_signal(file, spec.time_column).data[0]
    if values.shape[0] != len(spec.axes):
        raise SDTError(
            f"{file}: [{side}] holds {values.shape[0]} signal(s) for axes {spec.axes}; "
            f"name one column (or array row) per axis"
        )
    return values, times


def _signal(folder: Path, side: str, spec: PairSignal) -> Signal:
    values, times = _samples(folder, side, spec)
    values = values * TO_G[spec.units]
    label = f"[{side}] {spec.file}"
    if spec.part is not None:
        spec = spec.model_copy(update={"part": _cut(spec.part)})
    if times is None:
        return Signal(label, spec.part, tuple(spec.axes), values, float(spec.rate_hz or 0),
                      spec.start_s)  # fmt: skip
    if len(times) != values.shape[1] or len(times) < 3 or np.any(np.diff(times) <= 0):
        raise SDTError(
            f"{folder / spec.file}: [{side}] time_column {spec.time_column!r} must give one "
            f"strictly increasing time (s) per sample"
        )
    even = on_even_grid(times, values, f"{folder / spec.file} [{side}]")
    return Signal(label, spec.part, tuple(spec.axes), even.values, even.rate_hz,
                  even.start_s + spec.start_s, even.note, even.rate_sd_hz)  # fmt: skip


def load_toml_pair(path: str | Path, axes: list[str] | None = None) -> Pair:
    """The pair described by the TOML file at ``path``, on the axes both sides share."""
    path = Path(path)
    parsed = validate_file(_PairFile, read_toml(path, what="pair file"), path)
    try:
        ref = _signal(path.parent, "reference", parsed.reference)
        dev = _signal(path.parent, "device", parsed.device)
    except DataFileError as exc:
        raise SDTError(str(exc)) from None
    chosen = chosen_axes(path, ref.axes, dev.axes, axes, "both signals")

    def pick(s: Signal) -> Signal:
        rows = [s.axes.index(a) for a in chosen]
        return Signal(s.label, s.part, tuple(chosen), s.values[rows], s.rate_hz, s.start_s,
                      s.note, s.rate_sd_hz)  # fmt: skip

    files = [path.parent / parsed.reference.file, path.parent / parsed.device.file]
    return Pair(str(path), pick(ref), pick(dev), digest(path, *files))
