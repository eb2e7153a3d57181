"""Where each channel of a LabVIEW LVM file lies, and whether its header describes its samples.

lvm_read (:mod:`sdt_plugins.readers.lvm`) returns each segment's header cells
and its data as one array; this module matches them as LabVIEW writes them. A
header cell belongs to a data column: one cell per data column after the first
(``X_Columns`` ``One``, ``Multi``), one per channel (``No``). A channel's X
column is the column before it (``Multi``: one time column per channel,
LabVIEW's default for several channels), the first column (``One``: valid for
the channels at the first channel's ``Delta_X``, as LabVIEW's note "X values
guaranteed valid only for" says), or none (``No``). A channel holds its
header's ``Samples`` rows, its column empty below them (a channel shorter than
the others), or every row of its segment where rows were appended past the
first ``Samples`` (a file with one header).

A header is checked against the samples it describes, since a header kept on
other data reads them at a wrong rate, silently: a channel whose X column does
not step by its ``Delta_X`` (a copy resampled or decimated with its header
kept), whose ``X_Dimension`` is not ``Time`` (a spectrum), or whose segment
holds fewer rows than its ``Samples`` (a copy cut short) carries the reason
as its fault. ``Delta_X`` is read with the tolerance of its printed digits
(``0.000977`` s is 1/1024 s within 0.05 %), which is also the tolerance of a
manifest rate against it.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework.signals.rules import HEADER_RATE_TOLERANCE
from sdt_framework.signals.tokens import quote

#: LabVIEW writes LVM values with six digits after the decimal point (LabVIEW Help, "LabVIEW
#: Measurement Files"): two X values, each within half a unit of the sixth, differ from their
#: true difference by at most one unit
X_RESOLUTION_S = 1e-6
_NUMBER = re.compile(r"\s*[+-]?\d*(?:[.,](\d*))?(?:[eE]([+-]?\d+))?\s*")


@dataclass(frozen=True)
class Channel:
    """One channel in one segment: its data column, X column, header cells and length."""

    name: str
    column: int
    x_column: int | None
    delta: Any
    tolerance: float
    declared: int | None
    units: str | None
    dimension: str
    rows: int
    length: int


def _cell(values: Any, index: int) -> Any:
    return values[index] if isinstance(values, list) and 0 <= index < len(values) else None


def printed_tolerance(text: str | None, value: Any) -> float:
    """Relative tolerance of a rate from a time step printed as ``text``: half a unit of its
    last digit, at least :data:`HEADER_RATE_TOLERANCE`."""
    match = _NUMBER.fullmatch(text or "")
    try:
        step = abs(float(value))
    except (TypeError, ValueError):
        return HEADER_RATE_TOLERANCE
    if match is None or not match.group(0).strip() or not step:
        return HEADER_RATE_TOLERANCE
    half = 0.5 * 10.0 ** (int(match.group(2) or 0) - len(match.group(1) or ""))
    rel = half / step
    return max(HEADER_RATE_TOLERANCE, rel / (1 - rel) if rel < 1 else math.inf)


def _declared(value: Any) -> int | None:
    if isinstance(value, (int, float)) and math.isfinite(value) and value >= 0:
        return int(value)
    return None


def _length(values: np.ndarray, declared: int | None) -> int:
    """Rows a channel holds: its ``Samples`` when the column is empty below them (a shorter
    channel), every row where values go on past them (rows appended under one header)."""
    rows = len(values)
    if declared is None or rows < declared:
        return rows
    filled = np.flatnonzero(~np.isnan(values))
    return declared if not filled.size or filled[-1] < declared else rows


def segment_channels(lvm: dict[Any, Any], s: int, printed: list[str]) -> list[Channel]:
    """Every named or non-empty channel of segment ``s``, in column order; ``printed`` is the
    first segment's ``Delta_X`` cells as written (their digits give the tolerance)."""
    segment = lvm[s]
    layout = str(lvm.get("X_Columns", "One")).strip()
    offset = 0 if layout == "No" else 1
    names = list(segment.get("Channel names", []))
    if names[-1:] == ["Comment"]:
        names.pop()
    data = segment["data"]  # (rows, one column a name), as the reader's _load leaves it
    first_delta = None
    found = []
    for column, name in enumerate(names):
        values = data[:, column]
        if name == "X_Value" or (not name.strip() and np.isnan(values).all()):
            continue  # an X column, or the empty cell after a trailing separator
        cell = column - offset
        delta = _cell(segment.get("Delta_X"), cell)
        first_delta = delta if first_delta is None else first_delta
        if layout == "Multi":
            x_column = column - 1 if column and names[column - 1] == "X_Value" else None
        elif layout == "No" or names[:1] != ["X_Value"]:
            x_column = None
        else:  # One: the X column is the first channel's, and of those at its Delta_X
            x_column = 0 if same(delta, first_delta) else None
        declared = _declared(_cell(segment.get("Samples"), cell))
        units = str(_cell(segment.get("Y_Unit_Label"), cell) or "").strip() or None
        found.append(Channel(name, column, x_column, delta,
                             printed_tolerance(_cell(printed, cell), delta), declared, units,
                             str(_cell(segment.get("X_Dimension"), cell) or "").strip(),
                             len(data), _length(values, declared)))  # fmt: skip
    return found


def same(a: Any, b: Any) -> bool:
    """Two header values alike (numbers within 1e-9, NaN alike)."""
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=1e-9)
    return bool(a == b)


def spectrum_fault(path: Path, ch: Channel) -> str | None:
    """Why a channel whose X axis is not time (``X_Dimension`` ``Frequency``) is no signal."""
    if not ch.dimension or ch.dimension.lower() == "time":
        return None
    kind = "a spectrum" if ch.dimension.lower() == "frequency" else "not a time signal"
    return (
        f"{path}: channel {quote(ch.name)} is {kind}: its X_Dimension is "
        f"{quote(ch.dimension)}, not 'Time'; sdt reads time signals: save the time waveform"
    )


def x_column_fault(path: Path, ch: Channel, data: np.ndarray, s: int) -> str | None:
    """Why a channel's X column does not step by its ``Delta_X`` (within the printed digits of
    both), naming both and the ``Samples``; None when it does or there is no X column."""
    if ch.x_column is None or not isinstance(ch.delta, (int, float)) or not ch.delta > 0:
        return None
    x = np.asarray(data[: ch.length, ch.x_column], dtype=np.float64)
    bad = np.flatnonzero(~np.isfinite(x))
    x = x[: bad[0]] if bad.size else x
    if len(x) < 2:
        return None
    index = np.arange(len(x))
    off = np.abs(x - x[0] - index * ch.delta)
    allowed = index * ch.delta * ch.tolerance + X_RESOLUTION_S + 4e-16 * np.abs(x)
    wrong = np.flatnonzero(off > allowed)
    if not wrong.size:
        return None
    row = int(wrong[0])
    step = (x[-1] - x[0]) / (len(x) - 1)
    rate = f"{1 / step:.6g} Hz" if step > 0 else "no rate"
    samples = (
        f", and its Samples says {ch.declared:,} where the segment holds {ch.rows:,} rows"
        if ch.declared is not None and ch.declared != ch.rows
        else ""
    )
    return (
        f"{path}: channel {quote(ch.name)}: its header's Delta_X is {ch.delta:.7g} s "
        f"({1 / ch.delta:.6g} Hz) but its X column steps {step:.6g} s ({rate}) in segment "
        f"{s + 1} (row {row + 1} is at {x[row] - x[0]:.6g} s, Delta_X puts it at "
        f"{row * ch.delta:.6g} s){samples}; the header does not describe these samples (a "
        f"resampled or edited copy that kept its header?); export the file again, or correct "
        f"Delta_X"
    )


def truncated_fault(path: Path, ch: Channel, s: int) -> str | None:
    """A segment holding fewer rows than the channel's ``Samples`` lost its end."""
    if ch.declared is None or ch.rows >= ch.declared:
        return None
    return (
        f"{path}: truncated: segment {s + 1} holds {ch.rows:,} rows, its header's Samples says "
        f"{ch.declared:,}; the file was cut short; copy it again"
    )


def segments_fault(path: Path, name: str, found: list[Channel | None]) -> str | None:
    """Why a channel's segments are not acquisitions of one signal, or None."""
    first = found[0]
    assert first is not None
    for k, ch in enumerate(found[1:], start=2):
        if ch is None:
            return f"{path}: channel {quote(name)} is missing from segment {k}"
        if not same(first.delta, ch.delta):
            return (
                f"{path}: channel {quote(name)} has Delta_X {first.delta!r} s in segment 1 and "
                f"{ch.delta!r} s in segment {k}: its segments, read as acquisitions, are not "
                f"at one rate; split the file at segment {k}"
            )
        if first.units != ch.units:
            return (
                f"{path}: channel {quote(name)} has Y_Unit_Label {quote(first.units or '')} in "
                f"segment 1 and {quote(ch.units or '')} in segment {k}; split the file at "
                f"segment {k}"
            )
        if first.length != ch.length:
            return (
                f"{path}: channel {quote(name)} holds {first.length:,} samples in segment 1 and "
                f"{ch.length:,} in segment {k}; a signal's acquisitions must be equally long"
            )
    return None
