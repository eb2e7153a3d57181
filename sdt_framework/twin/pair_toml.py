"""A paired recording that is not an IDE file, described by a small TOML file.

Two tables, ``[reference]`` and ``[device]``, each naming one signal::

    [reference]
    file = "piezo.csv"            # any registered format; relative to this TOML's folder
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

A file is read by its registered reader (handed down by the caller, as
``sdt degrade`` reads one: :mod:`sdt_framework.signals.one_signal`): ``rate_hz``
and ``units`` are needed only where the file holds none (a TDMS, WAV, UFF58,
LVM or IDE file states its rate), and are refused naming both values where
they contradict it; ``variable`` names the signal of a file holding several.
A signal with a time column gets the same treatment as an IDE channel: its
rate measured from the timestamps, resampled onto an even grid with a note
when they stray (:mod:`sdt_framework.signals.timebase`).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, FiniteFloat, model_validator

from ..errors import SDTError
from ..signals.csv_rule import read_csv_signal
from ..signals.errors import DataFileError
from ..signals.one_signal import open_signal
from ..signals.timebase import on_even_grid
from ..toml_files import read_toml, validate_file
from ..units import TO_G, Unit
from .signals import Pair, Signal, chosen_axes, digest

__all__ = ["PairSignal", "is_pair_toml", "load_toml_pair"]

#: a part name is printed up to this many characters
PART_CHARACTERS = 60


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
    units: Unit | None = None
    part: str | None = None

    @model_validator(mode="after")
    def _consistent(self) -> PairSignal:
        if self.rate_hz is not None and self.time_column is not None:
            raise ValueError("give rate_hz or time_column, not both")
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
            raise ValueError(
                "columns and time_column are for CSV files (the rate comes from the file, or "
                "rate_hz)"
            )
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


def _samples(folder: Path, side: str, spec: PairSignal, readers: Sequence[Any]
             ) -> tuple[np.ndarray, np.ndarray | None, float]:  # fmt: skip
    """(values (axes, n) in g, timestamps or None, rate in Hz or 0 with timestamps)."""
    file = folder / spec.file
    if not file.is_file():
        raise SDTError(f"{file}: [{side}] file not found; paths are relative to the pair file")
    if spec.columns is not None:  # the signal columns and the time column in one read
        if spec.rate_hz is None and spec.time_column is None:
            raise SDTError(f"{file}: [{side}] a CSV holds no rate; give rate_hz or time_column")
        extra = [] if spec.time_column is None else [spec.time_column]
        table = read_csv_signal(file, [*spec.columns, *extra]).data
        times = table[-1] if extra else None
        return table[: len(spec.columns)] * TO_G[spec.units or "g"], times, spec.rate_hz or 0.0
    spelling = {
        "signal": f"variable = NAME in [{side}]",
        "rate": f"rate_hz in [{side}]",
        "units": f"units in [{side}]",
    }
    timed = (0.0, "time_column") if spec.time_column is not None else None
    opened = open_signal(file, readers, signal=spec.variable, rate_hz=spec.rate_hz,
                         units=spec.units, default_rate=timed, spelling=spelling)  # fmt: skip
    values = opened.read_g()
    if values.shape[0] != len(spec.axes):
        raise SDTError(
            f"{file}: [{side}] holds {values.shape[0]} signal(s) for axes {spec.axes}; "
            f"name one column (or array row) per axis"
        )
    times = None if timed is None else read_csv_signal(file, spec.time_column).data[0]
    return values, times, opened.rate_hz


def _signal(folder: Path, side: str, spec: PairSignal, readers: Sequence[Any]) -> Signal:
    values, times, rate = _samples(folder, side, spec, readers)
    label = f"[{side}] {spec.file}"
    if spec.part is not None:
        spec = spec.model_copy(update={"part": _cut(spec.part)})
    if times is None:
        return Signal(label, spec.part, tuple(spec.axes), values, rate, spec.start_s)
    if len(times) != values.shape[1] or len(times) < 3 or np.any(np.diff(times) <= 0):
        raise SDTError(
            f"{folder / spec.file}: [{side}] time_column {spec.time_column!r} must give one "
            f"strictly increasing time (s) per sample"
        )
    even = on_even_grid(times, values, f"{folder / spec.file} [{side}]")
    return Signal(label, spec.part, tuple(spec.axes), even.values, even.rate_hz,
                  even.start_s + spec.start_s, even.note, even.rate_sd_hz)  # fmt: skip


def load_toml_pair(path: str | Path, readers: Sequence[Any], axes: list[str] | None = None) -> Pair:
    """The pair described by the TOML file at ``path``, on the axes both sides share; its
    files read by ``readers`` (``registry.signal_readers()``, handed down)."""
    path = Path(path)
    parsed = validate_file(_PairFile, read_toml(path, what="pair file"), path)
    try:
        ref = _signal(path.parent, "reference", parsed.reference, readers)
        dev = _signal(path.parent, "device", parsed.device, readers)
    except DataFileError as exc:
        raise SDTError(str(exc)) from None
    chosen = chosen_axes(path, ref.axes, dev.axes, axes, "both signals")

    def pick(s: Signal) -> Signal:
        rows = [s.axes.index(a) for a in chosen]
        return Signal(s.label, s.part, tuple(chosen), s.values[rows], s.rate_hz, s.start_s,
                      s.note, s.rate_sd_hz)  # fmt: skip

    files = [path.parent / parsed.reference.file, path.parent / parsed.device.file]
    return Pair(str(path), pick(ref), pick(dev), digest(path, *files))
