"""Cut a long label in the middle, for wherever it is shown rather than stored.

A label from the user's data (a manifest's condition, a recording or a sweep
point's name) can be of any length. Where it is shown (a terminal line, a
figure's tick or legend) it keeps its first and last characters, which is
what tells two long names apart; result files and tables keep it whole. The
terminal (``cli.common.shorten_labels``) and the figures
(``report.style.figure_label``) cut the same way, here. A module of its own,
importing nothing, so the command line's start-up does not load the data
readers to shorten a message.
"""

from __future__ import annotations

__all__ = ["middle_cut"]


def middle_cut(text: str, half: int, *, count: bool = False) -> str:
    """``text`` as its first and last ``half`` characters joined by ``…``; with ``count``,
    followed by how long it was. The caller decides whether ``text`` is long enough to cut.

    >>> middle_cut("abcdefghij", 2)
    'ab…ij'
    >>> middle_cut("abcdefghij", 2, count=True)
    'ab…ij (10 characters)'
    """
    cut = f"{text[:half]}…{text[-half:]}"
    return f"{cut} ({len(text):,} characters)" if count else cut
