"""A recorder file of several channels, each a sensor with its own clock: what a reader lists.

Some formats hold more than signals: an enDAQ ``.IDE`` file holds several
channels (a piezo reference, a MEMS accelerometer, pressure...), each sampled
on its own clock with real timestamps, with a sensor table naming the part
behind each subchannel. A reader of such a format offers, besides
``scan``/``probe``/``read``, ``channels(path)`` (every :class:`Channel`, and
notes on how the file was read) and ``read_channel(path, channel, axes)`` (a
:class:`ChannelSignal`: the chosen axes of one channel together, on one even
grid at the rate measured from the timestamps); its ``scan`` names each axis
``CHANNEL:AXIS`` (:func:`axis_variable`, ``32:x``), as a manifest row's
``variable`` does. ``sdt twin check`` pairs two
channels of one file, ``sdt validate-noise --recording`` picks the channel of
the sensor's part, and ``sdt dataset inspect`` lists them, all through those
two functions, whatever the format.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SDTError

__all__ = [
    "Channel",
    "ChannelSignal",
    "Subchannel",
    "accelerometers",
    "axis_variable",
    "matches_part",
    "part_channel",
]


@dataclass(frozen=True)
class Subchannel:
    """One subchannel of a channel: an axis of an accelerometer, or another quantity."""

    index: int
    name: str
    axis: str | None  # "x", "y" or "z" for an accelerometer axis
    quantity: str
    units: str
    part: str | None


@dataclass(frozen=True)
class Channel:
    """One channel: its subchannels, sample count, time span and measured rates."""

    id: int
    name: str
    subchannels: tuple[Subchannel, ...]
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
class ChannelSignal:
    """Samples of one channel's subchannels in their units, on an even grid."""

    path: str
    channel: Channel
    subchannels: tuple[Subchannel, ...]
    start_s: float  # time of the first sample on the even grid
    rate_hz: float
    values: np.ndarray  # float64 (n_subchannels, n_samples)
    note: str | None  # set when the samples were resampled, or the file read in part
    rate_sd_hz: float = float("nan")  # standard error of rate_hz (timestamps about their line)

    @property
    def times(self) -> np.ndarray:
        """Time of each sample, s."""
        return self.start_s + np.arange(self.values.shape[1]) / self.rate_hz


def axis_variable(channel: int, axis: str) -> str:
    """The signal name of ``axis`` of ``channel`` (``32:x``): a manifest's ``variable``."""
    return f"{channel}:{axis}"


def accelerometers(channels: list[Channel]) -> list[Channel]:
    """The channels with at least one acceleration axis."""
    return [
        c
        for c in channels
        if any(s.axis and s.quantity.lower() == "acceleration" for s in c.subchannels)
    ]


def matches_part(channel: Channel, sensor: str) -> bool:
    """Whether a part of ``channel`` is the one ``sensor`` models (by the part's first word:
    ``adxl345`` or ``adxl345-fitted`` ~ ``ADXL345 Low-G DC Accelerometer``)."""
    tokens = {part.split()[0].lower() for part in channel.parts if part.split()}
    return any(sensor.lower().startswith(token) for token in tokens)


def part_channel(path: str | Path, channels: list[Channel], sensor: str) -> int:
    """The acceleration channel whose sensor table names the part ``sensor`` models."""
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
