"""CSV signal files: no rate or units held; read by the one CSV rule.

The rule (header, orientation, time column, values; :mod:`sdt_framework.signals.csv_rule`)
is shared with NLN-EMP's CSVs and a twin pair's columns, so it sits in the readers' kit;
what only this format's reader does is here: sizing a file before it is parsed.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

from sdt_framework import hookimpl
from sdt_framework.signals.csv_rule import read_csv_signal
from sdt_framework.signals.rules import SignalInfo
from sdt_framework.specs import ReaderSpec

#: peak bytes per value of parsing a CSV signal (read_csv_signal), on top of the command's:
#: about 42 B (78 B per value for a one-column CSV of 2e6 values in ``sdt degrade``, against
#: 31-36 B for NPY samples; ``/usr/bin/time -v``, :mod:`sdt_framework.signals.file_sizes`),
#: rounded up
PARSE_BYTES_PER_VALUE = 48

_HEAD = 65_536  # bytes of a CSV read to measure its lines
_SEPARATORS = re.compile(r"[,;\t ]+")


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The file's series (or the named column); the whole file is parsed."""
    parsed = read_csv_signal(path, variable)
    return SignalInfo(variable, *parsed.data.shape, note=parsed.note)


def scan(path: Path) -> list[SignalInfo]:
    """The file's series, as one signal of acquisitions."""
    return [probe(path, None)]


def read(path: Path, variable: str | None):
    """float64 (n_series, n_samples); every value checked finite."""
    return read_csv_signal(path, variable).data


def _is_number(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


def count(path: Path, variable: str | None) -> int | None:
    """Values in the file, estimated before it is parsed: its size over the mean length of its
    first data lines, times their columns (None when no data line is found)."""
    size = path.stat().st_size
    with path.open("rb") as handle:
        head = handle.read(_HEAD)
    lines = head.splitlines(keepends=True)
    if len(head) == _HEAD and len(lines) > 1:
        lines = lines[:-1]  # the last line read may be cut short
    skipped = 0
    data: list[bytes] = []
    for line in lines:
        tokens = [t for t in _SEPARATORS.split(line.decode("utf-8", "replace").strip()) if t]
        if tokens and all(_is_number(t) for t in tokens):
            data.append(line)
        elif not data:
            skipped += len(line)
    if not data:
        return None
    columns = len([t for t in _SEPARATORS.split(data[0].decode("utf-8", "replace").strip()) if t])
    per_line = sum(len(line) for line in data) / len(data)
    return math.ceil((size - skipped) / per_line) * columns


@hookimpl
def register_signal_readers(register):
    """Register the CSV reader."""
    register(
        ReaderSpec(
            name="csv",
            label="CSV",
            suffixes=(".csv",),
            description="Comma-separated numbers; a header and a time column are detected",
            source="sdt-framework (docs/data.md)",
            scan=scan,
            probe=probe,
            read=read,
            count=count,
            parse_bytes_per_value=PARSE_BYTES_PER_VALUE,
        )
    )
