"""Name the first bad line of a CSV file: the slow path, run only after a parse failed.

Fast parsers (pyarrow, numpy) say that a file is bad, not where in terms a
user can act on; this scan walks the physical lines once and describes the
first one that is not UTF-8, has the wrong number of cells, or holds a cell
that is empty, not a number, NaN or inf. Quoted cells are short tokens
(:func:`~sdt_framework.signals.tokens.quote`). Used by the CSV signal reader and
the NLN-EMP reader.
"""

from __future__ import annotations

import math
from pathlib import Path

from .tokens import quote

__all__ = ["locate_problem", "not_utf8"]


def not_utf8(number: int, raw: bytes, exc: UnicodeDecodeError) -> str:
    """``line N: not UTF-8 text (byte 0x.. at character C)``, with what to do."""
    return (
        f"line {number}: not UTF-8 text (byte 0x{raw[exc.start]:02x} at character "
        f"{exc.start + 1}); save the file as UTF-8"
    )


def locate_problem(path: Path, n_columns: int, first_line: int, labels: list[str]) -> str | None:
    """Scan ``path`` from ``first_line`` and describe its first bad line, or None.

    A bad line is one that is not UTF-8, has a number of cells other than
    ``n_columns``, or holds a cell that is empty, not a number, NaN or inf.
    ``labels`` names the columns. Blank lines are ignored, as the parser does.
    """
    with open(path, "rb") as handle:
        for number, raw in enumerate(handle, start=1):
            if number < first_line:
                continue
            try:
                line = raw.decode("utf-8-sig" if number == 1 else "utf-8")
            except UnicodeDecodeError as exc:
                return not_utf8(number, raw, exc)
            line = line.rstrip("\r\n")
            if not line.strip():
                continue
            cells = line.split(",")
            if len(cells) != n_columns:
                return f"line {number}: expected {n_columns} values, found {len(cells)}"
            for index, cell in enumerate(cells):
                where = f"line {number}, column {labels[index]}"
                if not cell.strip():
                    return f"{where}: empty value"
                try:
                    value = float(cell)
                except ValueError:
                    hint = "; separate values with ','" if ";" in cell or "\t" in cell else ""
                    return f"{where}: {quote(cell.strip())} is not a number{hint}"
                if not math.isfinite(value):
                    return f"{where}: non-finite value {quote(cell.strip())}"
    return None
