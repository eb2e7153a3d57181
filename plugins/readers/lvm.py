"""LabVIEW Measurement (``.lvm``) text files through lvm_read (ladisk, MIT).

lvm_read is the reader the pyuff authors keep beside it (maintained with a
test suite, on PyPI since 2015); it reads the header, per channel
``Delta_X``, ``Y_Unit_Label`` and ``Samples``, and each segment's data, with a
comma decimal separator where the header says so. It is called with its pickle
cache switched off (by default it writes ``FILE.lvm.pkl`` beside the file).
Each channel is a signal named by its header name; its rate is
``1 / Delta_X``; its segments (a LabVIEW logging loop writes one per
iteration) are its acquisitions and must be equally long, at one
``Delta_X`` and one ``Y_Unit_Label`` (a channel whose segments differ is
refused naming the segment). Where each channel lies (its data column, its X
column, its length), and whether its header describes its samples (its X
column steps by its ``Delta_X``, its ``X_Dimension`` is ``Time``), is
:mod:`sdt_plugins.readers.lvm_layout`'s; a channel it cannot read as it
stands is listed with the reason (its ``fault``). A column with no name and
no value (after a separator ending the column-name row) is no channel; two
columns of one name are refused, as one could not be told from the other. A
channel without a ``Y_Unit_Label`` carries a note: it is read in g.

lvm_read parses the text in Python (about 6 MB/s, up to 18 bytes of memory
per byte of file, measured below), so a file over :data:`LVM_MAX_BYTES` is
refused before parsing (TDMS holds the same data in binary). A file cut short
is refused: LabVIEW ends every line, so a last line without a line break is a
value cut off (``0.330`` of ``0.330112``), and a segment holding fewer rows
than a channel's ``Samples`` lost its end. lvm_read turns a cell it cannot
parse into NaN (refused by name); a header field that is not a number is named
with its line. A parsed file is kept for the next call on the same content
(SHA-256 of the file's bytes), the most recently used files up to
:data:`PARSED_KEEP_BYTES` of arrays: scanning, probing and reading each channel
of a file parse it once in a process, not once per call, even where a
benchmark probes every file of a campaign before it reads the first.
"""

from __future__ import annotations

import hashlib
import re
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np
from sdt_plugins.readers.lvm_layout import (
    Channel,
    segment_channels,
    segments_fault,
    spectrum_fault,
    truncated_fault,
    x_column_fault,
)

from sdt_framework import hookimpl
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.file_sizes import check_parse_size
from sdt_framework.signals.parsed import keep_parsed
from sdt_framework.signals.rules import (
    SignalInfo,
    finite,
    increment_rate,
    note_unstated_units,
    pick,
)
from sdt_framework.signals.tokens import brief, quote
from sdt_framework.specs import ReaderSpec

#: largest LVM file parsed, bytes: about 9 s and 1.1 GB of memory for lvm_read
LVM_MAX_BYTES = 50_000_000
#: peak memory of lvm_read per byte of file: measured 7.4 (8 channels), 11.4 (one channel
#: and its X column) and 18 (one channel, no X column) with ``/usr/bin/time -v`` on files of
#: 21-39 MB (2 vCPU, Python 3.11, lvm_read 1.26), rounded up
LVM_PARSE_BYTES_PER_BYTE = 22
_ADVICE = (
    "save the recording from LabVIEW as TDMS (Write To Measurement File, format TDMS), or "
    "split it into LVM files of at most 50 MB"
)
#: parsed arrays kept for the next call, bytes (:func:`~sdt_framework.signals.parsed.keep_parsed`;
#: the last file always). The largest file's arrays take up to 200 MB (a 2-byte cell, ``0``
#: and its separator, as 8 bytes), so this never holds more than the two files kept before.
PARSED_KEEP_BYTES = 256_000_000
#: header fields lvm_read evaluates as Python literals (``ast.literal_eval``)
_EVALUATED = ("Channels", "Delta_X", "X0", "Samples")
_AST_OBJECT = re.compile(r"<ast\.\w+ object at 0x[0-9a-fA-F]+>")


def _load(path: Path) -> dict[Any, Any]:
    """The parsed file (shared between calls on the same content: never modify it)."""
    size = check_parse_size(path, "LVM", LVM_MAX_BYTES, LVM_PARSE_BYTES_PER_BYTE, _ADVICE)
    _require_last_line(path, size)
    try:
        digest = hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    return _parse(path, digest)


def _nbytes(lvm: dict[Any, Any]) -> int:
    """Bytes of a parse's arrays (its header fields are a few hundred bytes)."""
    return sum(lvm[s]["data"].nbytes for s in range(int(lvm["Segments"])))


@keep_parsed(PARSED_KEEP_BYTES, _nbytes)
def _parse(path: Path, digest: str) -> dict[Any, Any]:
    """lvm_read's parse of ``path``, each segment's data as a float64 array of its columns;
    ``digest`` (of the bytes) keys the cache, so a changed file is parsed again."""
    import lvm_read

    try:
        lvm = lvm_read.read(str(path), read_from_pickle=False, dump_file=False)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except Exception as exc:  # lvm_read raises ValueError, KeyError, SyntaxError on bad headers
        raise DataFileError(_unparsed(path, exc)) from None
    for s in range(int(lvm["Segments"])):  # every named column in the array, rows or not
        width = len(lvm[s].get("Channel names", []))
        data = np.asarray(lvm[s]["data"], dtype=np.float64)
        data = data[:, :width] if data.ndim == 2 else np.empty((0, width))
        if data.shape[1] < width:
            data = np.pad(data, ((0, 0), (0, width - data.shape[1])), constant_values=np.nan)
        data.flags.writeable = False  # shared by later calls
        lvm[s]["data"] = data
    return lvm


def _require_last_line(path: Path, size: int) -> None:
    """LabVIEW ends every line: a file whose last byte is not a line break was cut."""
    with open(path, "rb") as handle:
        handle.seek(max(0, size - 64))
        tail = handle.read()
    if tail and not tail.endswith((b"\n", b"\r")):
        last = re.split(rb"[\t,;\r\n]", tail)[-1].decode("utf-8", "replace")
        raise DataFileError(
            f"{path}: truncated: its last line ends without a line break, in {quote(last)}; "
            f"LabVIEW ends every line, so the file was cut short and its last value may be "
            f"cut too; copy it again"
        )


def _unparsed(path: Path, exc: Exception) -> str:
    """The header field that is not a number, with its line; else lvm_read's message."""
    found = _bad_header_value(path)
    if found:
        return found
    if isinstance(exc, KeyError) and exc.args == ("data",):
        return (
            f"{path}: no column-name row: LabVIEW begins each segment's data with a row whose "
            f"first cell is 'X_Value', and lvm_read finds none (a file written by another "
            f"program, or edited); add that row, or export the file again from LabVIEW"
        )
    message = _AST_OBJECT.sub("a value that is not a number", str(exc))
    return f"{path}: not a readable LVM file (lvm_read: {brief(ValueError(message))})"


def _bad_header_value(path: Path) -> str | None:
    from ast import literal_eval

    separator, decimal = "\t", "."
    with open(path, encoding="utf8", errors="ignore") as handle:
        for number, line in enumerate(handle, 1):
            if line.startswith("Separator") and len(line.strip()) > 9:
                separator = line.strip()[9]  # as lvm_read reads it
            cells = line.rstrip("\r\n").split(separator)
            if cells[0] == "Decimal_Separator" and len(cells) == 2:
                decimal = cells[1]
            if cells[0] not in _EVALUATED:
                continue
            for value in cells[1:2] if cells[0] == "Channels" else cells[1:]:
                try:
                    if value:
                        literal_eval(value.replace(decimal, "."))
                except (ValueError, SyntaxError, TypeError, MemoryError, RecursionError):
                    return (
                        f"{path}: line {number}: field {quote(cells[0])} holds {quote(value)}, "
                        f"not a number; LabVIEW writes a number there (the file was edited or "
                        f"damaged)"
                    )
    return None


def _separator(path: Path) -> str:
    """The column separator, as lvm_read finds it (a ``Separator`` line in the first 21)."""
    with open(path, encoding="utf8", errors="ignore") as handle:
        for _, line in zip(range(22), handle, strict=False):
            if line.startswith("Separator") and len(line.strip()) > 9:
                return line.strip()[9]
    return "\t"


def _printed_deltas(path: Path) -> list[str]:
    """The first segment's ``Delta_X`` cells as written (their digits are their precision)."""
    separator = _separator(path)
    with open(path, encoding="utf8", errors="ignore") as handle:
        for line in handle:
            cells = line.rstrip("\r\n").split(separator)
            if cells[0] == "Delta_X":
                return cells[1:]
            if cells[0] == "X_Value":
                break
    return []


def _fault(path: Path, found: list[Channel | None], data: list[np.ndarray]) -> str | None:
    """Why a channel (its column in each segment; None where a segment lacks it) cannot be
    read as it stands: no name, not time, no rate, an X column or a row count its header
    does not describe, segments that differ."""
    first = found[0]
    assert first is not None
    if not first.name.strip():
        return (
            f"{path}: column {first.column + 1} holds values but has no name in the column-name "
            f"row; name it (LabVIEW writes a name for every channel)"
        )
    field = f"channel {quote(first.name)} Delta_X"
    fault = spectrum_fault(path, first) or increment_rate(path, first.delta, field)[1]
    for s, ch in enumerate(found):
        if ch is not None and not fault:
            fault = x_column_fault(path, ch, data[s], s) or truncated_fault(path, ch, s)
    return fault or segments_fault(path, first.name, found)


def _signals(path: Path, lvm: dict[Any, Any]) -> list[tuple[SignalInfo, list[Channel | None]]]:
    """Every channel: its signal, and its column in each segment."""
    printed = _printed_deltas(path)
    tables = [segment_channels(lvm, s, printed) for s in range(int(lvm["Segments"]))]
    data = [lvm[s]["data"] for s in range(len(tables))]
    counts = Counter(ch.name for ch in tables[0])
    infos, columns = [], []
    for first in tables[0]:
        if any(info.variable == first.name for info in infos):
            continue  # a name given to several columns: listed once, refused below
        found = [next((c for c in table if c.name == first.name), None) for table in tables]
        fault = _fault(path, found, data)
        if counts[first.name] > 1:
            fault = (
                f"{path}: {counts[first.name]} columns are named {quote(first.name)}; rename "
                f"them so that each channel has its own name"
            )
        rate = increment_rate(path, first.delta, f"channel {quote(first.name)} Delta_X")[0]
        infos.append(SignalInfo(first.name, len(tables), first.length, rate, first.units,
                                "Delta_X", first.tolerance, fault=fault,
                                units_field="Y_Unit_Label"))  # fmt: skip
        columns.append(found)
    return list(zip(note_unstated_units(path, infos), columns, strict=True))


def scan(path: Path) -> list[SignalInfo]:
    """Every channel (the file is parsed in full: LVM is text)."""
    return [info for info, _ in _signals(path, _load(path))]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """Channel ``variable`` (its header name), or the file's only one."""
    return pick(path, scan(path), variable)


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_segments, n_samples), all finite (a cell lvm_read could not parse is named)."""
    lvm = _load(path)
    signals = _signals(path, lvm)
    info = pick(path, [i for i, _ in signals], variable)
    found = next(columns for i, columns in signals if i.variable == info.variable)
    rows = [
        lvm[s]["data"][: ch.length, ch.column]
        for s, ch in enumerate(found)
        if ch is not None  # a channel missing from a segment has a fault: pick refused it
    ]
    return finite(path, np.ascontiguousarray(np.stack(rows), dtype=np.float64), "row", 1)


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
