"""The NLN-EMP CSV reader: files with header ``time,0,1,...``, read by the one CSV rule.

The header is checked here (NLN-EMP's own layout: a time column, then one
column per acquisition, named 0, 1, ...); the values are read by the rule
every CSV signal goes through (:func:`sdt_framework.signals.read_csv_signal`:
pyarrow, every value a finite number, the first bad line named by line and
column); the time column's step is checked here.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from sdt_framework.signals.csv_rule import read_csv_signal
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.tokens import quote

__all__ = ["CsvHeader", "parse_nln_csv", "read_header"]


@dataclass(frozen=True)
class CsvHeader:
    """What the first and last lines of an NLN-EMP CSV say, without parsing it."""

    columns: tuple[str, ...]
    time_step_s: float
    n_rows: int

    @property
    def sampling_rate_hz(self) -> float:
        """1 / time step, rounded to 1 mHz (the step is written in decimal)."""
        return round(1.0 / self.time_step_s, 3)


def _header(path: Path, line: bytes) -> list[str]:
    """The header cells; a message names the first wrong one (a short token, never the line)."""
    try:
        columns = line.decode("utf-8-sig").strip().split(",")
    except UnicodeDecodeError:
        raise DataFileError(f"{path}: line 1: not UTF-8 text; expected 'time,0,1,...'") from None
    expected = ["time", *map(str, range(len(columns) - 1))]
    pairs = enumerate(zip(columns, expected, strict=True))
    wrong = next((i for i, (a, b) in pairs if a != b), None)
    if len(columns) < 2 or wrong is not None:
        what = (
            f"column {wrong + 1} is {quote(columns[wrong])}, not {expected[wrong]!r}"
            if wrong is not None
            else f"{len(columns)} column"
        )
        raise DataFileError(
            f"{path}: line 1: header {what}; expected 'time,0,1,...' "
            f"(NLN-EMP format: a time column then one column per acquisition)"
        )
    return columns


def _last_line(path: Path, size: int) -> bytes:
    with open(path, "rb") as handle:
        handle.seek(max(0, size - 4096))
        tail = handle.read().rstrip(b"\r\n")
    return tail.rsplit(b"\n", 1)[-1]


def read_header(path: str | os.PathLike[str]) -> CsvHeader:
    """Columns, time step and row count from the first three and the last line.

    Cheap (reads a few kB) so that discovering a large archive is instant;
    :func:`parse_nln_csv` later checks every row.
    """
    path = Path(path)
    with open(path, "rb") as handle:
        head = [handle.readline() for _ in range(3)]
    columns = _header(path, head[0])
    try:
        t0, t1 = (float(line.split(b",", 1)[0]) for line in head[1:3])
        t_last = float(_last_line(path, path.stat().st_size).split(b",", 1)[0])
    except (ValueError, IndexError):
        raise DataFileError(
            f"{path}: lines 2-3 or the last line have no numeric time value; "
            f"need at least two data rows"
        ) from None
    step = t1 - t0
    if not step > 0:
        raise DataFileError(f"{path}: line 3: time does not increase (step {step!r} s)")
    return CsvHeader(tuple(columns), step, round((t_last - t0) / step) + 1)


def parse_nln_csv(path: str | os.PathLike[str], expected_step_s: float | None = None) -> np.ndarray:
    """Parse one NLN-EMP CSV into float64 (n_acquisitions, n_rows), checking every value.

    Parameters
    ----------
    path
        The CSV file.
    expected_step_s
        Time step the rows must follow (default: the step of the first two rows).

    Raises
    ------
    DataFileError
        Wrong header, ragged row, non-numeric text, empty or non-finite value,
        or an irregular time column; the message names the file and line.
    """
    path = Path(path)
    with open(path, "rb") as handle:
        columns = _header(path, handle.readline())
    data = read_csv_signal(path, columns).data  # the time column and every acquisition
    if data.shape[1] < 2:
        raise DataFileError(f"{path}: fewer than two data rows")
    time = data[0]
    step = expected_step_s if expected_step_s is not None else time[1] - time[0]
    off = np.abs(np.diff(time) - step) > 0.25 * step
    if off.any():
        row = int(np.flatnonzero(off)[0]) + 1
        raise DataFileError(
            f"{path}: line {row + 2}: time {time[row]!r} s breaks the {step:g} s step "
            f"(missing, repeated or shuffled rows)"
        )
    return data[1:]
