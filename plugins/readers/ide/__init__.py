"""enDAQ / Slam Stick ``.IDE`` recordings (idelib): the whole format, in this package.

One axis per signal, named ``CHANNEL:AXIS``; the rate is measured from the
timestamps (:mod:`sdt_framework.signals.timebase`), so a manifest's rate may
differ from it by 0.1 % (a MEMS part's real rate is a few percent off its
nominal one; 0.1 % is far below that). An IDE file is also a recorder file of
channels (:mod:`sdt_framework.signals.channels`): ``channels`` lists them and
``read_channel`` reads one channel's axes on one grid, which ``sdt twin``,
``sdt validate-noise --recording`` and ``sdt dataset inspect`` use.

- :mod:`.open`: idelib's import, refusing a file it could read only in part;
- :mod:`.parse`: the channels, their parts and measured rates, and samples.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.errors import SDTError
from sdt_framework.signals.channels import Channel, ChannelSignal, accelerometers, axis_variable
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.rules import SignalInfo, finite
from sdt_framework.specs import ReaderSpec

#: relative difference tolerated between a manifest rate and the timestamps' rate
IDE_RATE_TOLERANCE = 0.001


def _signal(path: Path, variable: str | None) -> ChannelSignal:
    from .parse import read_variable  # idelib: on use only

    try:
        return read_variable(path, variable)
    except SDTError as exc:
        raise DataFileError(str(exc)) from None


def scan(path: Path) -> list[SignalInfo]:
    """Every acceleration axis, with its units and the rate of its channel's timestamps."""
    from .parse import read_channels

    try:
        channels, notes = read_channels(path)
    except SDTError as exc:
        raise DataFileError(str(exc)) from None
    return [
        SignalInfo(axis_variable(c.id, s.axis), 1, c.samples, c.rate_hz, s.units, "timestamps",
                   IDE_RATE_TOLERANCE, f"{c.name} ({', '.join(c.parts) or '-'})",
                   "; ".join(notes) or None)
        for c in accelerometers(channels)
        for s in c.subchannels
        if s.axis
    ]  # fmt: skip


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The axis ``CHANNEL:AXIS`` (read in full: the rate comes from every timestamp)."""
    read = _signal(path, variable)
    return SignalInfo(variable, 1, read.values.shape[1], read.rate_hz,
                      read.subchannels[0].units, "timestamps", IDE_RATE_TOLERANCE,
                      note=read.note)  # fmt: skip


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (1, n_samples) on the even grid at the measured rate."""
    return finite(path, np.ascontiguousarray(_signal(path, variable).values))


def channels(path: Path) -> tuple[list[Channel], tuple[str, ...]]:
    """(every channel in id order, notes on how the file was read)."""
    from .parse import read_channels

    return read_channels(path)


def read_channel(path: Path, channel: int, axes: list[str] | None = None) -> ChannelSignal:
    """The ``axes`` (x/y/z or subchannel names; None: every one) of ``channel`` on one grid."""
    from .parse import read_ide

    return read_ide(path, channel, axes)


@hookimpl
def register_signal_readers(register):
    """Register the enDAQ IDE reader."""
    register(
        ReaderSpec(
            name="ide",
            label="enDAQ IDE",
            suffixes=(".ide",),
            description="enDAQ / Slam Stick recordings (idelib); rate from the timestamps",
            source="idelib (MIT), enDAQ",
            scan=scan,
            probe=probe,
            read=read,
            channels=channels,
            read_channel=read_channel,
        )
    )
