"""How many samples a signal file holds, read from its header before any sample is.

``sdt degrade``, ``sdt features extract`` and ``sdt twin check`` read one
signal file (or a pair) whole. Their size is known before reading, from the
file's reader (``ReaderSpec.count``, handed down with the readers): a
``.npy`` header gives the shape, a MAT file lists its arrays' shapes, a CSV's
size divided by the length of its first data lines gives its rows; an IDE
file's samples are bounded by its bytes. The command multiplies that by what
a sample costs it (below; a reader that parses text adds its own
``parse_bytes_per_value``) and refuses, before allocating, a file that cannot
fit in the memory available (:func:`sdt_framework.cli.guards.check_memory`).

The costs are peak resident bytes per input sample, measured with
``/usr/bin/time -v`` (maximum resident set size, less that of the same command
on a 20 000-sample file, 170-220 MB) on the reference machine (2 vCPU, Python
3.11), on random signals:

- ``sdt degrade x.npy``: 2·10^7 float64 samples in one row, adxl345 and
  adxl357 at ``--fs 20000`` (31 and 33 B), iis3dwb at ``--fs 100000`` (36 B),
  20 rows of 10^6 (12 B); a one-column CSV of 2·10^6 values: 78 B, so the
  parse adds about 42 B (the CSV reader's ``parse_bytes_per_value``).
- ``sdt features extract x.npy --fs 3200 --set paper8``: 2·10^7 samples as
  one row (32 B), 20 rows (40 B) and 2000 rows (34 B).
- ``sdt twin check pair.toml --sensor adxl345``: a 20 kHz reference and a
  3.2 kHz device, 3 axes each, as NPY files of 100, 200 and 300 s (56 to 59 B
  per value of the two files) and as CSV files with a time column, even or
  jittered, of 50 s (62 to 76 B per value, the time column counted); the
  shipped IDE files SSX66115.IDE and DAQ12006_000005.IDE: 58 and 42 B per
  byte of the file.

Each constant is the largest measured, rounded up by 10-30 %: the estimate
errs on the high side, by about that much.

Text formats that a library parses whole (LabVIEW LVM through lvm_read, UFF
through pyuff) are sized before they are parsed, in ``sdt dataset inspect``,
``sdt dataset manifest`` and every read: :func:`check_parse_size` refuses a
file over its format's stated bound, or one whose parse (the reader's measured
bytes of memory per byte of file) cannot fit in the memory available, naming
the size and what to do instead.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from .errors import DataFileError
from .files import reader_for
from .sizes import available_memory, human_bytes

__all__ = [
    "DEGRADE_BYTES_PER_SAMPLE",
    "FEATURES_BYTES_PER_SAMPLE",
    "TWIN_BYTES_PER_IDE_BYTE",
    "TWIN_BYTES_PER_SAMPLE",
    "check_parse_size",
    "file_samples",
]

#: peak bytes per input sample of ``sdt degrade`` (.npy; a text format adds its parse's)
DEGRADE_BYTES_PER_SAMPLE = 40
#: peak bytes per input sample of ``sdt features extract``
FEATURES_BYTES_PER_SAMPLE = 44
#: peak bytes per value (both files of a TOML pair, any time column counted) of ``twin check``
TWIN_BYTES_PER_SAMPLE = 80
#: peak bytes per byte of an IDE file of ``sdt twin check``
TWIN_BYTES_PER_IDE_BYTE = 64


def file_samples(
    path: str | os.PathLike[str], readers: Sequence[Any], variable: str | None = None
) -> int | None:
    """Values stored in the signal file at ``path`` (``variable``'s, or every signal's), from
    its header, through its reader among ``readers`` (``ReaderSpec.count``).

    A CSV's count is an estimate (its size over its first lines' length). None
    when the file cannot be sized this way (missing, a format whose reader
    gives no count, a damaged header): reading it then reports what is wrong.
    """
    path = Path(path)
    if not path.is_file():
        return None
    try:
        reader = reader_for(path, readers)
    except DataFileError:
        return None
    if reader.count is None:
        return None
    try:
        count = reader.count(path, variable)
    except (OSError, ValueError, EOFError, TypeError, NotImplementedError, DataFileError):
        return None
    return None if count is None else int(count)


def check_parse_size(path: Path, fmt: str, limit: int, bytes_per_byte: float, advice: str) -> int:
    """The size of ``path``, a ``fmt`` text file parsed whole, when it is at most ``limit``
    bytes and its parse (``bytes_per_byte`` of memory per byte) fits in the memory
    available; else a one-line refusal naming the size and ``advice``."""
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or exc})") from None
    if size > limit:
        raise DataFileError(
            f"{path}: a {human_bytes(size)} {fmt} file; sdt parses {fmt} text files up to "
            f"{human_bytes(limit)} (their reader holds the whole file as Python objects); "
            f"{advice}"
        )
    need = size * bytes_per_byte
    room = available_memory()
    if need > room:
        raise DataFileError(
            f"{path}: parsing this {human_bytes(size)} {fmt} file needs about "
            f"{human_bytes(need)} of memory, more than the {human_bytes(room)} available; "
            f"{advice}"
        )
    return size
