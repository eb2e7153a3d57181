"""The one rule for a CSV signal file, shared by the manifest reader and ``sdt degrade``.

1. **Header.** The first non-blank line is a header when one of its cells
   holds a letter and is not a number (``nan``, ``1e-3`` are numbers; a line
   ``0.1;0.2`` is a data line in the wrong format, reported as such). A header
   with no data row after it is refused.
2. **Orientation.** With a header, each column is a series (the header names
   them). Without one, the longer axis is time: a tall file (rows >= columns)
   holds one series per column, a wide one (``numpy.savetxt`` of an
   (acquisitions, samples) array) one series per row.
3. **Time column.** A column whose header name is time-like (``time``, ``t``,
   ``time_s``, ``time [s]``, ``timestamp``) is dropped. So is a leading series
   of at least :data:`MIN_TIME_SAMPLES` values that rises in a constant step
   (within 25 %, to allow for decimal rounding) when another series remains:
   an acceleration never does that. The caller gets a note naming the file.
   With ``variable`` (a manifest's named column) only that column is read.
4. **Values.** Every cell must be a finite number. The first that is not
   (ragged row, empty cell, text, NaN or inf, bytes that are not UTF-8) is
   named by line and column; a message quotes at most a short token of it
   (:func:`~sdt_framework.signals.tokens.quote`).

Parsing: pyarrow's CSV reader for files of up to :data:`PYARROW_MAX_COLUMNS`
columns (2.7x faster than ``numpy.loadtxt`` on 240 000 rows x 21 columns),
numpy's C ``loadtxt`` for wider ones (pyarrow took 44 s on 2 rows x 240 000
columns that ``loadtxt`` reads in 1 s; ``benchmarks/bench_csv_signal.py``).
Both read the same cells (quotes are not special); only when parsing fails is
the file scanned line by line (:mod:`~sdt_framework.signals.bad_line`), to name
the offending line.
"""

from __future__ import annotations

import os
import re
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.csv as pacsv
from numpy.typing import NDArray

from .bad_line import locate_problem, not_utf8
from .errors import DataFileError
from .tokens import brief, quote

__all__ = ["MIN_TIME_SAMPLES", "CsvSignal", "is_time_axis", "read_csv_signal"]

#: shortest leading series recognised as a time axis by its values alone
MIN_TIME_SAMPLES = 8
#: widest file parsed with pyarrow (per-column overhead); wider ones go to numpy.loadtxt
PYARROW_MAX_COLUMNS = 256
_TIME_NAME = re.compile(r"(t|time|timestamp)([ _\-\[(].*)?", re.IGNORECASE)


@dataclass(frozen=True)
class CsvSignal:
    """A parsed CSV signal: float64 ``data`` (n_series, n_samples), kept names, note."""

    data: NDArray[np.float64]
    names: tuple[str, ...] | None
    note: str | None


def _is_number(cell: str) -> bool:
    try:
        float(cell)
    except ValueError:
        return False
    return True


def _has_letter(cell: str) -> bool:
    return any(ch.isalpha() for ch in cell)


def is_time_axis(series: NDArray[np.float64]) -> bool:
    """True when ``series`` rises in a constant step (25 % tolerance), >= 8 values."""
    if series.size < MIN_TIME_SAMPLES:
        return False
    step = np.diff(series)
    median = float(np.median(step))
    return bool(median > 0 and np.all(np.abs(step - median) <= 0.25 * median))


def _first_lines(path: Path) -> tuple[int, str, bool]:
    """Number and text of the first non-blank line (0, "" if none), and whether more follow."""
    found: tuple[int, str] | None = None
    with open(path, "rb") as handle:
        for number, raw in enumerate(handle, start=1):
            if not raw.strip():
                continue
            if found is not None:
                return (*found, True)
            try:
                text = raw.decode("utf-8-sig" if number == 1 else "utf-8")
            except UnicodeDecodeError as exc:
                raise DataFileError(f"{path}: {not_utf8(number, raw, exc)}") from None
            found = (number, text.rstrip("\r\n"))
    return (*found, False) if found is not None else (0, "", False)


def _parse_arrow(path: Path, skip: int, n_columns: int) -> NDArray[np.float64] | None:
    """pyarrow's parse, or None when a value does not parse (the scanner names it)."""
    names = [f"f{i}" for i in range(n_columns)]
    try:
        table = pacsv.read_csv(
            path,
            read_options=pacsv.ReadOptions(skip_rows=skip, autogenerate_column_names=True),
            parse_options=pacsv.ParseOptions(quote_char=False),
            convert_options=pacsv.ConvertOptions(
                column_types=dict.fromkeys(names, pa.float64()),
                null_values=[""],
                strings_can_be_null=False,
            ),
        )
    except pa.ArrowInvalid:
        return None
    if table.num_columns != n_columns or any(c.null_count for c in table.columns):
        return None
    # one series per row in memory (rows x columns seen through .T): a column read whole
    # is one contiguous series, so selecting every column in order copies nothing more
    columns = np.stack([c.to_numpy() for c in table.columns]).astype(np.float64, copy=False)
    return columns.T


def _parse(path: Path, skip: int, labels: list[str], start: int) -> NDArray[np.float64]:
    if len(labels) <= PYARROW_MAX_COLUMNS:
        matrix = _parse_arrow(path, skip, len(labels))
        if matrix is None:
            found = locate_problem(path, len(labels), start, labels)
            raise DataFileError(f"{path}: {found or 'cannot read numbers'}")
        if not np.isfinite(matrix).all():
            found = locate_problem(path, len(labels), start, labels)
            raise DataFileError(f"{path}: {found or 'non-finite value'}")
        return matrix
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UserWarning)  # "input contained no data"
            matrix = np.loadtxt(
                path,
                delimiter=",",
                dtype=np.float64,
                skiprows=skip,
                ndmin=2,
                encoding="utf-8-sig",
                comments=None,
            )
    except (ValueError, UnicodeDecodeError) as exc:
        found = locate_problem(path, len(labels), start, labels)
        raise DataFileError(f"{path}: {found or f'cannot read numbers ({brief(exc)})'}") from None
    if matrix.size and not np.isfinite(matrix).all():
        found = locate_problem(path, len(labels), start, labels)
        raise DataFileError(f"{path}: {found or 'non-finite value'}")
    return matrix


def read_csv_signal(
    path: str | os.PathLike[str], variable: str | Sequence[str] | None = None
) -> CsvSignal:
    """Read a CSV signal file by the module's rule.

    Parameters
    ----------
    path
        The CSV file.
    variable
        A header name, or several: read only those columns, in that order (no
        time detection), from one pass over the file.

    Returns
    -------
    CsvSignal
        ``data`` float64 (n_series, n_samples), all finite; ``note`` says which
        time column was dropped, else None.

    Raises
    ------
    DataFileError
        Empty file, header without data, only a time column, unknown
        ``variable``, or a bad value; the message names the file and line.
    """
    path = Path(path)
    try:
        number, text, more = _first_lines(path)
        size = path.stat().st_size
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    if number == 0:
        raise DataFileError(f"{path}: no data ({size} bytes); expected numbers separated by ','")
    cells = [cell.strip().strip('"').strip() for cell in text.split(",")]
    header = any(_has_letter(cell) and not _is_number(cell) for cell in cells)
    labels = [quote(c) for c in cells] if header else [str(i + 1) for i in range(len(cells))]
    if header and not more:
        raise DataFileError(
            f"{path}: line {number} is a header ({labels[0]}, ...) and no data row follows"
        )
    try:
        matrix = _parse(path, number if header else 0, labels, number + 1 if header else number)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    if header or matrix.shape[0] >= matrix.shape[1]:
        series, axis = matrix.T, "column"
    else:
        series, axis = matrix, "row"
    names = tuple(cells) if header else None
    if variable is not None:
        return _select(path, series, names, variable)
    keep = np.ones(len(series), dtype=bool)
    if names is not None:
        keep &= np.array([not _TIME_NAME.fullmatch(name) for name in names])
    dropped = [i for i in range(len(series)) if not keep[i]]
    if not dropped and len(series) > 1 and is_time_axis(series[0]):
        keep[0] = False
        dropped = [0]
    if keep.all():
        return CsvSignal(np.ascontiguousarray(series), names, None)
    if not keep.any():
        raise DataFileError(
            f"{path}: only a time {axis} ({labels[dropped[0]] if header else 1}); no signal to read"
        )
    which = ", ".join(f"{axis} {labels[i] if header else i + 1}" for i in dropped)
    time = series[dropped[0]]
    step = f" (step {float(np.median(np.diff(time))):.6g})" if time.size > 1 else ""
    kept = series[keep]
    note = (
        f"{path}: {which} read as time{step} and dropped; "
        f"{len(kept)} series of {kept.shape[1]} samples remain"
    )
    return CsvSignal(
        np.ascontiguousarray(kept),
        None if names is None else tuple(n for n, k in zip(names, keep, strict=True) if k),
        note,
    )


def _select(
    path: Path,
    series: NDArray[np.float64],
    names: tuple[str, ...] | None,
    variable: str | Sequence[str],
) -> CsvSignal:
    wanted = (variable,) if isinstance(variable, str) else tuple(variable)
    if not wanted:
        raise DataFileError(f"{path}: no column named to read; give at least one header name")
    if names is None:
        raise DataFileError(f"{path}: no header line, so column {quote(wanted[0])} cannot be found")
    for name in wanted:
        if name not in names:
            shown = ", ".join(quote(n) for n in names[:8]) + (", ..." if len(names) > 8 else "")
            raise DataFileError(f"{path}: no column {quote(name)}; the header has {shown}")
    index = [names.index(name) for name in wanted]
    chosen = series if index == list(range(len(series))) else series[index]
    return CsvSignal(np.ascontiguousarray(chosen), wanted, None)
