"""Quote a piece of a user's file in an error message without leaking whole lines.

Error messages travel far: to the terminal, to ``summary.json`` and
``skipped.csv`` of a results folder, to a bug report. A manifest row may point
at any file, including a symlink to a system file, so a message quotes at most
a short token of a file's content (the offending cell, cut to
:data:`TOKEN_LIMIT` characters), never a line. Library messages that may embed
file content (pyarrow, numpy, scipy) are cut the same way. A value read from a
file (a sample, a rate) is shown as a plain number, never as NumPy's
``np.float64(nan)``: :func:`shown` (defined with the error types, below every
layer, so that the units that may not import the data layer use the same one).
"""

from __future__ import annotations

from ..errors import shown

__all__ = ["MESSAGE_LIMIT", "TOKEN_LIMIT", "brief", "quote", "shown"]

#: characters of a file's content a message may quote: longer than any number
#: written with 17 significant digits, shorter than a typical line of a
#: configuration or credentials file
TOKEN_LIMIT = 20
#: characters of a library's own error message kept (its first line only)
MESSAGE_LIMIT = 60


def quote(text: object, limit: int = TOKEN_LIMIT) -> str:
    """``repr`` of ``text`` cut to ``limit`` characters, with ``…`` when cut.

    >>> quote("1.5")
    "'1.5'"
    >>> quote("root:x:0:0:root:/root:/bin/bash")
    "'root:x:0:0:root:/roo…'"
    """
    text = str(text)
    if len(text) <= limit:
        return repr(text)
    return repr(text[:limit] + "…")


def brief(exc: BaseException, limit: int = MESSAGE_LIMIT) -> str:
    """First line of an exception's message, cut to ``limit`` characters."""
    lines = str(exc).strip().splitlines()
    text = lines[0] if lines else type(exc).__name__
    return text if len(text) <= limit else text[:limit] + "…"
