"""enDAQ / Slam Stick ``.IDE`` recordings (idelib): one axis per signal, named ``CHANNEL:AXIS``.

The rate is measured from the timestamps (:mod:`sdt_framework.data.timebase`),
so a manifest's rate may differ from it by 0.1 % (a MEMS part's real rate is
a few percent off its nominal one; 0.1 % is far below that).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, finite
from sdt_framework.data.recording import DataFileError
from sdt_framework.errors import SDTError
from sdt_framework.specs import ReaderSpec

#: relative difference tolerated between a manifest rate and the timestamps' rate
IDE_RATE_TOLERANCE = 0.001


def _signal(path: Path, variable: str | None):
    from sdt_framework.data.ide import read_variable  # idelib: on use only

    try:
        return read_variable(path, variable)
    except SDTError as exc:
        raise DataFileError(str(exc)) from None


def scan(path: Path) -> list[SignalInfo]:
    """Every acceleration axis, with its units and the rate of its channel's timestamps."""
    from sdt_framework.data.ide import accelerometers, read_channels

    try:
        channels, notes = read_channels(path)
    except SDTError as exc:
        raise DataFileError(str(exc)) from None
    return [
        SignalInfo(f"{c.id}:{s.axis}", 1, c.samples, c.rate_hz, s.units, "timestamps",
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
        )
    )
