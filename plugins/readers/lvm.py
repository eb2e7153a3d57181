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
refused naming the segment). A header cell is matched to its data column as
LabVIEW writes them: one cell per data column after the first (``X_Columns``
``One`` or ``Multi``), one per channel (``No``).

lvm_read parses the text in Python (about 6 MB/s, up to 18 bytes of memory
per byte of file, measured below), so a file over :data:`LVM_MAX_BYTES` is
refused before parsing (TDMS holds the same data in binary). A file cut short
is refused: LabVIEW ends every line, so a last line without a line break is a
value cut off (``0.330`` of ``0.330112``), and a segment holding fewer rows
than its header's ``Samples`` lost its end. lvm_read turns a cell it cannot
parse into NaN (refused by name); a header field that is not a number is named
with its line.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, finite, increment_rate, pick
from sdt_framework.data.recording import DataFileError
from sdt_framework.data.signal_sizes import check_parse_size
from sdt_framework.data.tokens import brief, quote
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
#: header fields lvm_read evaluates as Python literals (``ast.literal_eval``)
_EVALUATED = ("Channels", "Delta_X", "X0", "Samples")
_AST_OBJECT = re.compile(r"<ast\.\w+ object at 0x[0-9a-fA-F]+>")

Table = dict[str, tuple[int, Any, str | None]]  # channel -> (data column, Delta_X, units)


def _load(path: Path) -> dict[Any, Any]:
    import lvm_read

    size = check_parse_size(path, "LVM", LVM_MAX_BYTES, LVM_PARSE_BYTES_PER_BYTE, _ADVICE)
    _require_last_line(path, size)
    try:
        lvm = lvm_read.read(str(path), read_from_pickle=False, dump_file=False)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except Exception as exc:  # lvm_read raises ValueError, KeyError, SyntaxError on bad headers
        raise DataFileError(_unparsed(path, exc)) from None
    _require_samples(path, lvm)
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


def _require_samples(path: Path, lvm: dict[Any, Any]) -> None:
    """A segment holding fewer rows than its header's ``Samples`` lost its end."""
    for s in range(int(lvm["Segments"])):
        rows = len(lvm[s]["data"])
        declared = [v for v in lvm[s].get("Samples", []) if isinstance(v, (int, float))]
        declared = [v for v in declared if math.isfinite(v)]
        if declared and rows < max(declared):
            raise DataFileError(
                f"{path}: truncated: segment {s + 1} holds {rows:,} rows, its header's Samples "
                f"says {int(max(declared)):,}; the file was cut short; copy it again"
            )


def _unparsed(path: Path, exc: Exception) -> str:
    """The header field that is not a number, with its line; else lvm_read's message."""
    found = _bad_header_value(path)
    if found:
        return found
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


def _cell(values: Any, index: int) -> Any:
    return values[index] if isinstance(values, list) and 0 <= index < len(values) else None


def _table(lvm: dict[Any, Any], s: int) -> Table:
    """Every channel of segment ``s``: its data column, ``Delta_X`` and units."""
    segment = lvm[s]
    offset = 0 if str(lvm.get("X_Columns", "One")).strip() == "No" else 1
    names = [n for n in segment.get("Channel names", []) if n != "Comment"]
    table: Table = {}
    for column, name in enumerate(names):
        if name == "X_Value":
            continue
        units = str(_cell(segment.get("Y_Unit_Label"), column - offset) or "").strip() or None
        table.setdefault(name, (column, _cell(segment.get("Delta_X"), column - offset), units))
    return table


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return (math.isnan(a) and math.isnan(b)) or math.isclose(a, b, rel_tol=1e-9)
    return bool(a == b)


def _segment_fault(path: Path, name: str, tables: list[Table]) -> str | None:
    """Why channel ``name``'s segments are not acquisitions of one signal, or None."""
    _, delta, units = tables[0][name]
    for k, table in enumerate(tables[1:], start=2):
        if name not in table:
            return f"{path}: channel {quote(name)} is missing from segment {k}"
        _, other, other_units = table[name]
        if not _same(delta, other):
            return (
                f"{path}: channel {quote(name)} has Delta_X {delta!r} s in segment 1 and "
                f"{other!r} s in segment {k}: its segments, read as acquisitions, are not at "
                f"one rate; split the file at segment {k}"
            )
        if units != other_units:
            return (
                f"{path}: channel {quote(name)} has Y_Unit_Label {quote(units or '')} in "
                f"segment 1 and {quote(other_units or '')} in segment {k}; split the file at "
                f"segment {k}"
            )
    return None


def _segments(path: Path, lvm: dict[Any, Any]) -> list[np.ndarray]:
    segments = [np.atleast_2d(lvm[s]["data"]) for s in range(int(lvm["Segments"]))]
    lengths = {len(s) for s in segments}
    if len(lengths) > 1:
        raise DataFileError(
            f"{path}: its {len(segments)} segments hold {sorted(lengths)} rows; a signal's "
            f"acquisitions must be equally long"
        )
    return segments


def _signals(path: Path, lvm: dict[Any, Any]) -> list[SignalInfo]:
    segments = _segments(path, lvm)
    tables = [_table(lvm, s) for s in range(len(segments))]
    infos = []
    for name, (_, delta, units) in tables[0].items():
        rate, fault = increment_rate(path, delta, f"channel {quote(name)} Delta_X")
        fault = fault or _segment_fault(path, name, tables)
        infos.append(SignalInfo(name, len(segments), len(segments[0]), rate, units, "Delta_X",
                                fault=fault))  # fmt: skip
    return infos


def scan(path: Path) -> list[SignalInfo]:
    """Every channel (the file is parsed in full: LVM is text)."""
    return _signals(path, _load(path))


def probe(path: Path, variable: str | None) -> SignalInfo:
    """Channel ``variable`` (its header name), or the file's only one."""
    return pick(path, scan(path), variable)


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_segments, n_samples), all finite (a cell lvm_read could not parse is named)."""
    lvm = _load(path)
    name = str(pick(path, _signals(path, lvm), variable).variable)
    segments = _segments(path, lvm)
    columns = [_table(lvm, s)[name][0] for s in range(len(segments))]
    data = np.stack([s[:, c] for s, c in zip(segments, columns, strict=True)]).astype(np.float64)
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
