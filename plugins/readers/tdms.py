"""NI TDMS files (NI-DAQmx, LabVIEW, SignalExpress) through npTDMS.

Each channel is a signal named ``GROUP/CHANNEL`` (names may hold ``/``: NI
loggers put dates in group names, so a channel is found by its two names,
never by splitting the joined one). Its rate is ``1 / wf_increment`` and its
units the ``unit_string`` property (a channel without one carries a note: it
is read in g); a channel whose x axis is not time (``wf_xunit_string``
``Hz``: a spectrum) is listed and refused. Samples are read
scaled (npTDMS applies the file's ``NI_Scale`` chain, as NI's own software
does), so a DAQmx channel scaled to g reads in g and one left in volts says
``Volts`` (refused by a manifest, which wants an acceleration). ``wf_start_time``
is shown by ``sdt dataset inspect``. A file whose last segment is cut short is
refused, naming how many values the channel should hold and how many it holds.

npTDMS keeps the last value a property is given in any segment and applies it
to every sample, so a channel whose ``wf_increment``, ``unit_string`` or
``NI_Scale`` changes between segments after it holds values would read at one
rate, in one unit, all wrong but the last segment's. The segments' metadata is
walked once more (:class:`_Watch`, npTDMS's own reader noting each segment's
properties) and such a channel is refused, naming the property, both values and
the segment.
"""

from __future__ import annotations

import logging
import math
from collections import Counter
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.errors import InternalError
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.rules import (
    SignalInfo,
    as_acquisitions,
    increment_rate,
    note_unstated_units,
    pick,
)
from sdt_framework.signals.tokens import brief, quote
from sdt_framework.specs import ReaderSpec


def _load(path: Path, group: str | None = None, name: str | None = None):
    """The file's metadata (no ``group``), or one channel's scaled samples, read alone
    (``TdmsFile.open`` streams: the other channels are not read)."""
    from nptdms import TdmsFile
    from nptdms.log import log_manager

    cut: list[str] = []

    def catch(record: logging.LogRecord) -> bool:
        """npTDMS warns (on its own console handler) where the file is cut short: keep it."""
        cut.append(record.getMessage())
        return False

    log_manager.console_handler.addFilter(catch)
    try:
        if group is None:
            found = (TdmsFile.read_metadata(path), _changes(path))
        else:
            with TdmsFile.open(path) as tdms:
                found = tdms[group][name][:]
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except InternalError:
        raise
    except Exception as exc:  # npTDMS raises ValueError, KeyError, struct.error... on bad bytes
        raise DataFileError(
            f"{path}: not a readable TDMS file (npTDMS: {brief(exc)}); a copy cut short?"
        ) from None
    finally:
        log_manager.console_handler.removeFilter(catch)
    if cut:
        raise DataFileError(
            f"{path}: truncated: its last segment holds less data than its header declares "
            f"(npTDMS); the file is not used; copy it from the DAQ again"
        )
    return found


#: channel properties that must hold for every sample: rate, units, scaling
WATCHED = ("wf_increment", "unit_string", "NI_Number_Of_Scales")


def _watched(name: str) -> bool:
    return name in WATCHED or name.startswith("NI_Scale[")


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return math.isclose(float(a), float(b), rel_tol=1e-9)
    return bool(a == b)


def _shown(value: Any) -> str:
    return f"{value:.6g}" if isinstance(value, float) else quote(value)


def _changes(path: Path) -> dict[str, str]:
    """{channel path: what changes} for each channel whose rate, units or scaling property
    takes another value in a later segment, after the channel holds values."""
    from nptdms.reader import TdmsReader

    class _Watch(TdmsReader):
        """npTDMS's metadata reader, noting each segment's properties as it merges them."""

        def __init__(self, file: Path) -> None:
            super().__init__(file)
            self.segment = 0
            self.before: dict[str, int] = {}
            self.seen: dict[tuple[str, str], tuple[Any, int]] = {}
            self.changes: dict[str, str] = {}

        def _update_object_metadata(self, segment: Any) -> None:
            self.before = {p: m.num_values for p, m in self.object_metadata.items()}
            super()._update_object_metadata(segment)

        def _update_object_properties(self, properties: Any) -> None:
            self.segment += 1
            for where, items in (properties or {}).items():
                for name, value in items:
                    if _watched(name):
                        self._note(where, name, value)
            super()._update_object_properties(properties)

        def _note(self, where: str, name: str, value: Any) -> None:
            old = self.seen.get((where, name))
            held = self.before.get(where, 0)
            if old is not None and held and not _same(old[0], value) and where not in self.changes:
                self.changes[where] = (
                    f"changes its {name} from {_shown(old[0])} (segment {old[1]}) to "
                    f"{_shown(value)} at segment {self.segment}, after {held:,} values"
                )
            self.seen[(where, name)] = (value, self.segment)

    reader = _Watch(path)
    try:
        reader.read_metadata()
    finally:
        reader.close()
    if reader.object_metadata and not reader.segment:  # npTDMS renamed what _Watch overrides
        raise InternalError(
            "npTDMS's TdmsReader no longer merges properties per segment as "
            "plugins/readers/tdms.py expects; pin npTDMS or update _Watch"
        )
    return reader.changes


#: characters of a channel's ``GROUP/CHANNEL`` quoted in a message: enough to tell channels
#: whose group names share a long date prefix (``07/09/2012 06:58:23 PM - Digital Input - ...``)
NAME_LIMIT = 100
#: x-axis units (``wf_xunit_string``) of a time waveform; empty is npTDMS's and DAQmx's default
TIME_UNITS = ("", "s", "sec", "second", "seconds")
#: x-axis units of a spectrum (a frequency axis)
FREQUENCY_UNITS = ("hz", "khz", "1/s")


def _x_axis_fault(path: Path, variable: str, props: dict[str, Any]) -> str | None:
    """Why a channel whose x axis is not time (a spectrum in Hz, a time in ms) is no signal."""
    unit = str(props.get("wf_xunit_string", "")).strip()
    xname = str(props.get("wf_xname", "")).strip()
    what = f"{path}: channel {quote(variable, NAME_LIMIT)}"
    if unit.lower() in FREQUENCY_UNITS or xname.lower() == "frequency":
        field = f"wf_xunit_string is {quote(unit)}" if unit else f"wf_xname is {quote(xname)}"
        return (
            f"{what} is a spectrum, not a time signal: its {field} (its x axis is frequency); "
            f"sdt reads time signals: log the time waveform, not its spectrum"
        )
    if unit.lower() not in TIME_UNITS:
        return (
            f"{what}: its wf_xunit_string is {quote(unit)}, not seconds; sdt reads wf_increment "
            f"as a time step in seconds: write the waveform with its x axis in s"
        )
    return None


def _info(path: Path, group, channel, changes: dict[str, str]) -> SignalInfo:
    props = channel.properties
    variable = f"{group.name}/{channel.name}"
    name = quote(variable, NAME_LIMIT)
    rate, fault = None, None
    if "wf_increment" in props:
        rate, fault = increment_rate(path, props["wf_increment"], f"channel {name} wf_increment")
    fault = _x_axis_fault(path, variable, props) or fault
    if channel.path in changes:
        fault = (
            f"{path}: channel {name} {changes[channel.path]}; npTDMS applies the last value to "
            f"every sample, so the channel is not one record; split the file at that segment, "
            f"or write one rate, unit and scale per channel"
        )
    start = props.get("wf_start_time")
    return SignalInfo(
        variable,
        1,
        len(channel),
        rate,
        str(props["unit_string"]) if props.get("unit_string") else None,
        "wf_increment" if rate else "",
        label=f"start {np.datetime_as_string(start, unit='s')}" if start is not None else "",
        fault=fault,
        units_field="unit_string",
    )


def _channels(path: Path) -> list[tuple[SignalInfo, str, str]]:
    """(signal, group name, channel name) of every channel, from the metadata alone. Names may
    hold '/' (NI loggers put dates in group names), so a channel is found by its two names,
    never by splitting ``GROUP/CHANNEL``; two channels that join to one name are refused."""
    tdms, changes = _load(path)
    found = [(_info(path, g, c, changes), g.name, c.name) for g in tdms.groups()
             for c in g.channels()]  # fmt: skip
    joined = Counter(info.variable for info, _, _ in found)
    infos = [
        info if joined[info.variable] == 1 else replace(info, fault=(
            f"{path}: {joined[info.variable]} channels are named "
            f"{quote(info.variable, NAME_LIMIT)} (group and channel names joined by '/'); "
            f"rename a group or a channel so that each GROUP/CHANNEL is one channel"))
        for info, _, _ in found
    ]  # fmt: skip
    infos = note_unstated_units(path, infos)
    return [(info, g, c) for info, (_, g, c) in zip(infos, found, strict=True)]


def scan(path: Path) -> list[SignalInfo]:
    """Every channel, from the metadata alone."""
    return [info for info, _, _ in _channels(path)]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The channel ``GROUP/CHANNEL``, or the file's only one."""
    return pick(path, scan(path), variable)


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (1, n_samples), scaled, all finite; the length is checked against the metadata."""
    channels = _channels(path)
    info = pick(path, [i for i, _, _ in channels], variable)
    group, name = next((g, c) for i, g, c in channels if i.variable == info.variable)
    data = _load(path, group, name)
    if len(data) != info.n_samples:
        raise DataFileError(
            f"{path}: channel {info.variable!r} should hold {info.n_samples:,} values and holds "
            f"{len(data):,}; the file is cut short"
        )
    return as_acquisitions(path, np.asarray(data))


@hookimpl
def register_signal_readers(register):
    """Register the TDMS reader."""
    register(
        ReaderSpec(
            name="tdms",
            label="TDMS",
            suffixes=(".tdms",),
            description="NI TDMS channels (npTDMS); rate from wf_increment, units from unit_string",
            source="npTDMS (LGPL-3.0); NI TDMS file format",
            sniff=lambda head: head.startswith(b"TDSm"),
            scan=scan,
            probe=probe,
            read=read,
        )
    )
