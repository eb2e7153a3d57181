"""NI TDMS files (NI-DAQmx, LabVIEW, SignalExpress) through npTDMS.

Each channel is a signal named ``GROUP/CHANNEL``. Its rate is ``1 /
wf_increment`` and its units the ``unit_string`` property; samples are read
scaled (npTDMS applies the file's ``NI_Scale`` chain, as NI's own software
does), so a DAQmx channel scaled to g reads in g and one left in volts says
``Volts`` (refused by a manifest, which wants an acceleration). ``wf_start_time``
is shown by ``sdt dataset inspect``. A file whose last segment is cut short is
refused, naming how many values the channel should hold and how many it holds.
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, as_acquisitions, pick, rate_from_increment
from sdt_framework.data.recording import DataFileError
from sdt_framework.data.tokens import brief
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
            found = TdmsFile.read_metadata(path)
        else:
            with TdmsFile.open(path) as tdms:
                found = tdms[group][name][:]
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
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


def _info(path: Path, group, channel) -> SignalInfo:
    props = channel.properties
    rate = None
    if "wf_increment" in props:
        rate = rate_from_increment(path, props["wf_increment"], f"channel {channel.name!r} "
                                   "wf_increment")  # fmt: skip
    start = props.get("wf_start_time")
    return SignalInfo(
        f"{group.name}/{channel.name}",
        1,
        len(channel),
        rate,
        str(props["unit_string"]) if props.get("unit_string") else None,
        "wf_increment" if rate else "",
        label=f"start {np.datetime_as_string(start, unit='s')}" if start is not None else "",
    )


def scan(path: Path) -> list[SignalInfo]:
    """Every channel, from the metadata alone."""
    tdms = _load(path)
    return [_info(path, g, c) for g in tdms.groups() for c in g.channels()]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The channel ``GROUP/CHANNEL``, or the file's only one."""
    return pick(path, scan(path), variable)


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (1, n_samples), scaled, all finite; the length is checked against the metadata."""
    info = probe(path, variable)
    group, _, name = str(info.variable).partition("/")
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
