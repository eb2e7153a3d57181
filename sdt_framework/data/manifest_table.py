"""Read a manifest table (CSV or Parquet) into rows that know where they came from.

A CSV manifest is read with Python's :mod:`csv` module, not pandas, so that
every problem can be named by its line: an empty (0-byte) file, bytes that
are not UTF-8, a row with more or fewer fields than the header (a ragged row:
pandas would stop with a tokenizer traceback or fill the gap silently), a
repeated column name, a header with no row under it. Values quoted from the
file are short tokens (:func:`~sdt_framework.signals.tokens.quote`). A cell that
sdt wrote spreadsheet-safe (``'=x`` for a label ``=x``,
:mod:`sdt_framework.csv_cells`) reads back as the label.
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path

from ..csv_cells import unescape_cell
from ..errors import SDTError
from ..inputs import require_regular_file
from ..signals.tokens import brief, quote

__all__ = ["ManifestRow", "read_manifest_rows"]


@dataclass(frozen=True)
class ManifestRow:
    """One manifest row: ``where`` (``"line 5"`` or ``"row 3"``), its number, its cells."""

    where: str
    number: int
    cells: dict[str, str]


def _decode(path: Path, data: bytes) -> str:
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[: exc.start].count(b"\n") + 1
        raise SDTError(
            f"manifest {path} line {line}: not UTF-8 text (byte 0x{data[exc.start]:02x}); "
            f"save the manifest as UTF-8"
        ) from None


def _csv_rows(path: Path, data: bytes) -> tuple[list[str], list[ManifestRow]]:
    if not data.strip():
        raise SDTError(
            f"manifest {path} is empty ({len(data)} bytes); its line 1 must be the header "
            f"path,sampling_rate_hz,condition,severity,recording_id,channel"
        )
    reader = csv.reader(io.StringIO(_decode(path, data), newline=""))
    header: list[str] | None = None
    rows: list[ManifestRow] = []
    try:
        for cells in reader:
            if not any(cell.strip() for cell in cells):
                continue  # a blank line, as pandas skips it
            if header is None:
                header = [unescape_cell(cell.strip()) for cell in cells]
                header_line = reader.line_num
                continue
            if len(cells) != len(header):
                raise SDTError(
                    f"manifest {path} line {reader.line_num}: {len(cells)} fields, the header "
                    f"(line {header_line}) has {len(header)}; quote a value holding ','"
                )
            line = reader.line_num
            cells = [unescape_cell(cell) for cell in cells]
            rows.append(ManifestRow(f"line {line}", line, dict(zip(header, cells, strict=True))))
    except csv.Error as exc:
        raise SDTError(f"manifest {path} line {reader.line_num}: {brief(exc)}") from None
    assert header is not None  # data.strip() is not empty
    return header, rows


def _parquet_rows(path: Path) -> tuple[list[str], list[ManifestRow]]:
    import pyarrow as pa
    import pyarrow.parquet as pq

    try:
        table = pq.read_table(path)
    except (pa.ArrowException, OSError) as exc:
        raise SDTError(f"manifest {path}: not a readable Parquet file ({brief(exc)})") from None
    header = [str(name) for name in table.column_names]
    columns = [table.column(i).to_pylist() for i in range(table.num_columns)]
    rows = []
    for index, values in enumerate(zip(*columns, strict=True)):
        cells = {name: "" if v is None else str(v) for name, v in zip(header, values, strict=True)}
        rows.append(ManifestRow(f"row {index + 1}", index + 1, cells))
    return header, rows


def read_manifest_rows(path: Path) -> tuple[list[str], list[ManifestRow]]:
    """The header and the non-blank rows of a ``.csv`` or ``.parquet`` manifest.

    Raises
    ------
    SDTError
        Missing, unreadable, empty, not UTF-8, ragged, a repeated column name,
        or a header without rows; the message names the file and the line.
    """
    require_regular_file(path, "manifest")
    if not path.is_file():
        what = "is a folder" if path.is_dir() else "not found"
        raise SDTError(f"manifest {path} {what}; give the path of a .csv or .parquet file")
    suffix = path.suffix.lower()
    if suffix not in {".csv", ".parquet"}:
        raise SDTError(f"manifest {path}: unsupported type {suffix!r}; use .csv or .parquet")
    if suffix == ".parquet":
        header, rows = _parquet_rows(path)
    else:
        try:
            data = path.read_bytes()
        except OSError as exc:
            raise SDTError(
                f"manifest {path}: cannot read ({exc.strerror or brief(exc)}); "
                f"check its permissions"
            ) from None
        header, rows = _csv_rows(path, data)
    seen: set[str] = set()
    for name in header:
        if name in seen:
            raise SDTError(f"manifest {path}: column {quote(name)} appears twice in the header")
        seen.add(name)
    if not rows:
        raise SDTError(f"manifest {path}: a header and no rows; add one row per signal file")
    return header, rows
