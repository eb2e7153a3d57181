"""The two ways a signal file is refused: unusable (skipped, listed) or holding no numbers.

Defined with the reader kit, below the datasets, so that a reader plugin, a
manifest and a command that reads one file raise the same types; the data
layer shows them as ``sdt_framework.data.DataFileError`` and
``SignalTypeError``.
"""

from __future__ import annotations

from ..errors import SDTError

__all__ = ["DataFileError", "SignalTypeError"]


class DataFileError(SDTError):
    """A data file that cannot be used; the message names the file and the row."""


class SignalTypeError(SDTError):
    """A signal file holding booleans, complex numbers, text...: refused, never converted.

    Unlike a :class:`DataFileError` (a missing or unreadable file, listed as
    skipped), such a file was read: converting it would change the data
    without a word (0/1 g, a dropped imaginary part), so the run stops.
    """
