"""LabVIEW Measurement (``.lvm``) text files through lvm_read (ladisk, MIT).

lvm_read is the reader the pyuff authors keep beside it (maintained with a
test suite, on PyPI since 2015); it reads the header, per channel
``Delta_X`` and ``Y_Unit_Label``, and each segment's data, with a comma
decimal separator where the header says so. It is called with its pickle
cache switched off (by default it writes ``FILE.lvm.pkl`` beside the file).
Each channel is a signal named by its header name; its rate is
``1 / Delta_X``; its segments (a LabVIEW logging loop writes one per
iteration) are its acquisitions and must be equally long. lvm_read turns a
cell it cannot parse into NaN; such a cell is refused by name.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, finite, pick, rate_from_increment
from sdt_framework.data.recording import DataFileError
from sdt_framework.data.tokens import brief
from sdt_framework.specs import ReaderSpec


def _load(path: Path) -> dict[Any, Any]:
    import lvm_read

    try:
        return lvm_read.read(str(path), read_from_pickle=False, dump_file=False)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except Exception as exc:  # lvm_read raises ValueError, KeyError, SyntaxError on bad headers
        raise DataFileError(f"{path}: not a readable LVM file (lvm_read: {brief(exc)})") from None


def _channels(path: Path, lvm: dict[Any, Any]) -> list[tuple[str, int, int, float, str | None]]:
    """(name, data column, channel index, rate, units) of every channel of segment 0."""
    segment = lvm[0]
    names = [n for n in segment.get("Channel names", []) if n != "Comment"]
    out = []
    index = 0
    for column, name in enumerate(names):
        if name == "X_Value":
            continue
        rate = rate_from_increment(path, segment["Delta_X"][index], f"channel {name!r} Delta_X")
        units = (segment.get("Y_Unit_Label") or [""] * (index + 1))[index].strip() or None
        out.append((name, column, index, rate, units))
        index += 1
    return out


def _segments(path: Path, lvm: dict[Any, Any]) -> list[np.ndarray]:
    segments = [np.atleast_2d(lvm[s]["data"]) for s in range(int(lvm["Segments"]))]
    lengths = {len(s) for s in segments}
    if len(lengths) > 1:
        raise DataFileError(
            f"{path}: its {len(segments)} segments hold {sorted(lengths)} rows; a signal's "
            f"acquisitions must be equally long"
        )
    return segments


def scan(path: Path) -> list[SignalInfo]:
    """Every channel (the file is parsed in full: LVM is text)."""
    lvm = _load(path)
    segments = _segments(path, lvm)
    return [
        SignalInfo(name, len(segments), len(segments[0]), rate, units, "Delta_X")
        for name, _, _, rate, units in _channels(path, lvm)
    ]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """Channel ``variable`` (its header name), or the file's only one."""
    return pick(path, scan(path), variable)


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_segments, n_samples), all finite (a cell lvm_read could not parse is named)."""
    lvm = _load(path)
    name = pick(path, scan(path), variable).variable
    column = next(c for n, c, _, _, _ in _channels(path, lvm) if n == name)
    data = np.stack([s[:, column] for s in _segments(path, lvm)]).astype(np.float64)
    return finite(path, np.ascontiguousarray(data), "row", 1)


@hookimpl
def register_signal_readers(register):
    """Register the LabVIEW LVM reader."""
    register(
        ReaderSpec(
            name="lvm",
            label="LabVIEW LVM",
            suffixes=(".lvm",),
            description="LabVIEW Measurement text files (lvm_read); rate from Delta_X",
            source="lvm_read (MIT, ladisk); NI LVM file format",
            sniff=lambda head: head.lstrip(b"\xef\xbb\xbf").startswith(b"LabVIEW Measurement"),
            scan=scan,
            probe=probe,
            read=read,
        )
    )
