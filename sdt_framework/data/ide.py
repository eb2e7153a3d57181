"""enDAQ / Slam Stick recorder files (``.IDE``), read through their maintained reader, idelib.

An IDE file holds several channels (a piezo reference, a MEMS accelerometer,
pressure, orientation...), each sampled on its own clock with real
timestamps, and a sensor table naming the parts. What sdt needs from one:

- the channels, their subchannels (axes), units and part names, and the rate
  *measured* from the timestamps (a MEMS part's real output rate differs from
  its nominal ODR by a few percent: 3134 Hz for an ADXL345 set to 3200 Hz);
- one channel's samples in g, on an even time grid at the measured rate
  (:mod:`.timebase`: resampled with a note when the timestamps stray).

EBML parsing is idelib's (MIT), never done here.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SDTError
from .timebase import EVEN_TOLERANCE, measured_rate, on_even_grid, require_one_record

__all__ = [
    "EVEN_TOLERANCE",
    "IdeChannel",
    "IdeSignal",
    "IdeSubchannel",
    "accelerometers",
    "inspect_ide",
    "is_ide",
    "matches_part",
    "part_channel",
    "read_channels",
    "read_ide",
    "read_variable",
]


@dataclass(frozen=True)
class IdeSubchannel:
    """One subchannel of a channel: an axis of an accelerometer, or another quantity."""

    index: int
    name: str
    axis: str | None  # "x", "y" or "z" for an accelerometer axis
    quantity: str
    units: str
    part: str | None


@dataclass(frozen=True)
class IdeChannel:
    """One channel: its subchannels, sample count, time span and measured rates."""

    id: int
    name: str
    subchannels: tuple[IdeSubchannel, ...]
    samples: int
    start_s: float
    end_s: float
    rate_hz: float  # slope of the timestamps (least squares)
    median_rate_hz: float  # 1 / median interval
    time_fault: str | None = None  # why the timestamps are not one record (a gap, a step)

    @property
    def parts(self) -> list[str]:
        """The part names of the sensor table behind this channel's subchannels."""
        return sorted({s.part for s in self.subchannels if s.part})

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready form."""
        return {
            "channel": self.id,
            "name": self.name,
            "parts": self.parts,
            "samples": self.samples,
            "start_s": self.start_s,
            "end_s": self.end_s,
            "rate_hz": self.rate_hz,
            "median_rate_hz": self.median_rate_hz,
            "time_fault": self.time_fault,
            "subchannels": [vars(s) for s in self.subchannels],
        }


@dataclass(frozen=True)
class IdeSignal:
    """Samples of one channel's subchannels in their units, on an even grid."""

    path: str
    channel: IdeChannel
    subchannels: tuple[IdeSubchannel, ...]
    start_s: float  # time of the first sample on the even grid
    rate_hz: float
    values: np.ndarray  # float64 (n_subchannels, n_samples)
    note: str | None  # set when the samples were resampled
    rate_sd_hz: float = float("nan")  # standard error of rate_hz (timestamps about their line)

    @property
    def times(self) -> np.ndarray:
        """Time of each sample, s."""
        return self.start_s + np.arange(self.values.shape[1]) / self.rate_hz


def is_ide(path: str | os.PathLike[str]) -> bool:
    """Whether ``path`` is named as an IDE file."""
    return Path(path).suffix.lower() == ".ide"


def _open(path: str | os.PathLike[str]) -> Any:
    """The imported file (:func:`.ide_open.open_ide`: a damaged file is refused)."""
    from .ide_open import open_ide

    return open_ide(path)


def _axis(name: str) -> str | None:
    first = name.strip().split(" ")[0].lower()
    return first if first in ("x", "y", "z") else None


def _describe(channel: Any) -> tuple[IdeChannel, np.ndarray]:
    session = channel.getSession()
    rows = 1 + len(channel.subchannels)
    data = (
        np.asarray(session.arraySlice(), dtype=np.float64)
        if len(session)
        else np.empty((rows, 0))  # a channel that recorded nothing
    )
    times = data[0] * 1e-6  # microseconds
    rate, median, _, _ = measured_rate(times)
    try:
        require_one_record(times, f"channel {channel.id}")
        fault = None
    except SDTError as exc:
        fault = str(exc)
    subs = tuple(
        IdeSubchannel(
            i,
            str(s.name),
            _axis(str(s.name)),
            str(s.units[0]),
            str(s.units[1]),
            getattr(getattr(s, "sensor", None), "name", None),
        )
        for i, s in enumerate(channel.subchannels)
    )
    start, end = (float(times[0]), float(times[-1])) if len(times) else (0.0, 0.0)
    return IdeChannel(
        int(channel.id), str(channel.name), subs, len(times), start, end, rate, median, fault
    ), data


def inspect_ide(path: str | os.PathLike[str]) -> list[IdeChannel]:
    """Every channel of the IDE file at ``path``, in id order."""
    return read_channels(path)[0]


def read_channels(path: str | os.PathLike[str]) -> tuple[list[IdeChannel], tuple[str, ...]]:
    """(every channel of the IDE file at ``path`` in id order, notes on how it was read)."""
    opened = _open(path)
    try:
        doc = opened.doc
        return [_describe(doc.channels[cid])[0] for cid in sorted(doc.channels)], opened.notes
    finally:
        opened.doc.close()


def read_ide(
    path: str | os.PathLike[str],
    channel: int,
    subchannels: list[str] | None = None,
) -> IdeSignal:
    """Samples of ``channel`` (by id), its ``subchannels`` (axes ``x``/``y``/``z`` or names;
    default every one), on an even time grid at the measured rate."""
    opened = _open(path)
    doc = opened.doc
    try:
        if channel not in doc.channels:
            found = ", ".join(f"{c} ({doc.channels[c].name})" for c in sorted(doc.channels))
            raise SDTError(f"{path}: no channel {channel}; the file holds channels {found}")
        info, data = _describe(doc.channels[channel])
    finally:
        doc.close()
    chosen = list(info.subchannels)
    if subchannels is not None:
        by_key = {s.axis: s for s in info.subchannels if s.axis} | {
            s.name: s for s in info.subchannels
        }
        missing = [k for k in subchannels if k not in by_key]
        if missing:
            names = ", ".join(f"{s.axis or s.name!r}" for s in info.subchannels)
            raise SDTError(
                f"{path}: channel {channel} has no subchannel {missing[0]!r}; it has {names}"
            )
        chosen = [by_key[k] for k in subchannels]
    if info.samples < 2:
        raise SDTError(f"{path}: channel {channel} holds {info.samples} samples; nothing to read")
    times = data[0] * 1e-6
    values = data[[1 + s.index for s in chosen]]
    _require_finite(path, channel, times, values)
    even = on_even_grid(times, values, f"{Path(path).name} channel {channel}")
    note = "; ".join(filter(None, (*opened.notes, even.note))) or None
    return IdeSignal(str(path), info, tuple(chosen), even.start_s, even.rate_hz, even.values,
                     note, even.rate_sd_hz)  # fmt: skip


def _require_finite(path: str | os.PathLike[str], channel: int, times: np.ndarray,
                    values: np.ndarray) -> None:  # fmt: skip
    """Refuse a channel holding a NaN or infinite sample (idelib's reading of damaged bytes)."""
    bad = ~np.isfinite(values).all(axis=0) | ~np.isfinite(times)
    if bad.any():
        first = int(np.argmax(bad))
        raise SDTError(
            f"{path}: channel {channel}, sample {first} (at {times[first]:.4f} s): "
            f"{int(bad.sum())} non-finite value(s); the file is damaged there"
        )


def accelerometers(channels: list[IdeChannel]) -> list[IdeChannel]:
    """The channels with at least one acceleration axis."""
    return [
        c
        for c in channels
        if any(s.axis and s.quantity.lower() == "acceleration" for s in c.subchannels)
    ]


def part_channel(path: str | os.PathLike[str], channels: list[IdeChannel], sensor: str) -> int:
    """The acceleration channel whose sensor table names the part ``sensor`` models
    (``adxl345`` or ``adxl345-fitted`` ~ ``ADXL345 Low-G DC Accelerometer``)."""
    listed = accelerometers(channels)
    found = [c for c in listed if matches_part(c, sensor)]
    if len(found) != 1:
        names = ", ".join(f"{c.id} ({', '.join(c.parts) or c.name})" for c in listed)
        why = "none" if not found else "more than one"
        raise SDTError(
            f"{path}: {why} of the acceleration channels {names} is the part of {sensor!r}; "
            f"name the channel"
        )
    return found[0].id


def matches_part(channel: IdeChannel, sensor: str) -> bool:
    """Whether a part of ``channel`` is the one ``sensor`` models (by the part's first word)."""
    tokens = {part.split()[0].lower() for part in channel.parts if part.split()}
    return any(sensor.lower().startswith(token) for token in tokens)


def read_variable(path: str | os.PathLike[str], variable: str | None) -> IdeSignal:
    """One axis of an IDE file named as a manifest's ``variable``: ``CHANNEL:AXIS`` (``32:x``)."""
    channel, _, axis = (variable or "").partition(":")
    if not channel.strip().isdigit() or not axis.strip():
        found = ", ".join(
            f"{c.id}:{s.axis}" for c in accelerometers(inspect_ide(path)) for s in c.subchannels
            if s.axis
        )  # fmt: skip
        raise SDTError(
            f"{path}: an IDE row names its signal as variable = CHANNEL:AXIS (got "
            f"{variable!r}); this file holds {found}"
        )
    return read_ide(path, int(channel), [axis.strip().lower()])
