"""CSV cells that a spreadsheet shows as text, never runs as a formula; read back unchanged.

A spreadsheet (Excel, LibreOffice Calc, Google Sheets) opening a CSV takes a
cell that begins with ``=``, ``+``, ``-``, ``@``, a tab, a carriage return or
a line feed as a formula: a condition named ``=HYPERLINK("http://...")`` in a
manifest would become a live link in manifest.csv and results.csv. OWASP's
guidance (OWASP www-community, "CSV Injection", pages/attacks/CSV_Injection.md)
is that no cell may begin with one of these characters, and to prepend a
single quote to such a cell. Every CSV sdt writes goes through
:func:`escape_cell` (one text) or :func:`escape_frame` (a table, its header
too), and every CSV sdt reads back through :func:`unescape_cell` /
:func:`unescape_frame`, so a label survives the round trip exactly:

- a text that begins with any number of ``'`` and then one of those
  characters gets one more ``'`` in front (``=x`` -> ``'=x``, ``'=x`` ->
  ``''=x``), so that reading drops exactly one;
- a plain number (``-1.5``, ``+2e3``) is left as it is: a spreadsheet reads it
  as a number, never a formula;
- numbers stored as numbers, and every other text, are written unchanged.

The field separator and quotes inside a cell are RFC 4180's job, done by the
CSV writers themselves (Python's :mod:`csv`, pandas): a cell holding ``,`` or
``"`` is quoted, so nothing inside it starts a new cell. A module of its own,
importing nothing heavy, as the manifest writer and the benchmark's tables both
use it.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    import pandas as pd

__all__ = ["FORMULA_STARTS", "escape_cell", "escape_frame", "unescape_cell", "unescape_frame"]

#: first characters that make a spreadsheet read a cell as a formula (OWASP, "CSV Injection")
FORMULA_STARTS = "=+-@\t\r\n"
_RISKY = re.compile(rf"'*[{re.escape(FORMULA_STARTS)}]")
_ESCAPED = re.compile(rf"'+[{re.escape(FORMULA_STARTS)}]")
_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


def escape_cell(text: str) -> str:
    """``text`` as a CSV cell no spreadsheet runs: one ``'`` in front of a risky start.

    >>> escape_cell("=1+2"), escape_cell("'@x"), escape_cell("-1.5"), escape_cell("healthy")
    ("'=1+2", "''@x", '-1.5', 'healthy')
    """
    if _RISKY.match(text) and not _NUMBER.fullmatch(text):
        return "'" + text
    return text


def unescape_cell(text: str) -> str:
    """The text :func:`escape_cell` was given (one ``'`` off an escaped cell).

    >>> unescape_cell("'=1+2"), unescape_cell("''@x"), unescape_cell("'quoted'")
    ('=1+2', "'@x", "'quoted'")
    """
    return text[1:] if _ESCAPED.match(text) else text


def _map_text(frame: pd.DataFrame, cell: Any, pattern: re.Pattern[str]) -> pd.DataFrame:
    """``frame`` with ``cell`` applied to every text value matching ``pattern`` (and names)."""
    import pandas as pd

    out = frame.copy(deep=False)
    for index in range(frame.shape[1]):
        column = frame.iloc[:, index]
        if isinstance(column.dtype, pd.CategoricalDtype):
            renamed = [cell(c) if isinstance(c, str) else c for c in column.cat.categories]
            out.isetitem(index, column.cat.rename_categories(renamed))
            continue
        if not (column.dtype == object or pd.api.types.is_string_dtype(column.dtype)):
            continue  # numbers, booleans, dates: never a formula in a CSV
        try:
            hits = column.str.match(pattern.pattern).fillna(False).to_numpy(bool)
        except AttributeError:  # an object column that holds no text
            continue
        if hits.any():
            changed = column.copy()
            changed[hits] = [cell(v) for v in column[hits]]
            out.isetitem(index, changed)
    out.columns = [cell(n) if isinstance(n, str) else n for n in frame.columns]
    return out


def escape_frame(frame: pd.DataFrame) -> pd.DataFrame:
    """A copy of ``frame`` to write as CSV: :func:`escape_cell` on every text cell and name."""
    return _map_text(frame, escape_cell, _RISKY)


def unescape_frame(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` as read from a CSV sdt wrote: :func:`unescape_cell` on every text and name."""
    return _map_text(frame, unescape_cell, _ESCAPED)
