"""The channels of an enDAQ / Slam Stick ``.IDE`` file, read through idelib.

An IDE file holds several channels (a piezo reference, a MEMS accelerometer,
pressure, orientation...), each sampled on its own clock with real
timestamps, and a sensor table naming the parts. What sdt needs from one
(:mod:`sdt_framework.signals.channels` holds the types):

- the channels, their subchannels (axes), units and part names, and the rate
  *measured* from the timestamps (a MEMS part's real output rate differs from
  its nominal ODR by a few percent: 3134 Hz for an ADXL345 set to 3200 Hz);
- one channel's samples in their units, on an even time grid at the measured
  rate (:mod:`sdt_framework.signals.timebase`: resampled with a note when the
  timestamps stray).

EBML parsing is idelib's (MIT), never done here; :mod:`.open` opens the file
and refuses one idelib could read only in part.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework.errors import SDTError
from sdt_framework.signals.channels import Channel, ChannelSignal, Subchannel, accelerometers
from sdt_framework.signals.timebase import measured_rate, on_even_grid, require_one_record

__all__ = ["inspect_ide", "read_channels", "read_ide", "read_variable"]


def _open(path: str | os.PathLike[str]) -> Any:
    """The imported file (:func:`.open.open_ide`: a damaged file is refused)."""
    from .open import open_ide

    return open_ide(path)


def _axis(name: str) -> str | None:
    first = name.strip().split(" ")[0].lower()
    return first if first in ("x", "y", "z") else None


def _describe(channel: Any) -> tuple[Channel, np.ndarray]:
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
        Subchannel(
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
    return Channel(
        int(channel.id), str(channel.name), subs, len(times), start, end, rate, median, fault
    ), data


def inspect_ide(path: str | os.PathLike[str]) -> list[Channel]:
    """Every channel of the IDE file at ``path``, in id order."""
    return read_channels(path)[0]


def read_channels(path: str | os.PathLike[str]) -> tuple[list[Channel], tuple[str, ...]]:
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
) -> ChannelSignal:
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
    return ChannelSignal(str(path), info, tuple(chosen), even.start_s, even.rate_hz, even.values,
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


def read_variable(path: str | os.PathLike[str], variable: str | None) -> ChannelSignal:
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
