"""How many samples a signal file holds, read from its header before any sample is.

``sdt degrade``, ``sdt features extract`` and ``sdt twin check`` read one
signal file (or a pair) whole. Their size is known before reading: a ``.npy``
header gives the shape, a MAT file lists its arrays' shapes, a CSV's size
divided by the length of its first data lines gives its rows, and an IDE
file's samples are bounded by its bytes. The command multiplies that by what
a sample costs it (below) and refuses, before allocating, a file that cannot
fit in the memory available (:func:`sdt_framework.cli.guards.check_memory`).

The costs are peak resident bytes per input sample, measured with
``/usr/bin/time -v`` (maximum resident set size, less that of the same command
on a 20 000-sample file, 170-220 MB) on the reference machine (2 vCPU, Python
3.11), on random signals:

- ``sdt degrade x.npy``: 2·10^7 float64 samples in one row, adxl345 and
  adxl357 at ``--fs 20000`` (31 and 33 B), iis3dwb at ``--fs 100000`` (36 B),
  20 rows of 10^6 (12 B); a one-column CSV of 2·10^6 values: 78 B, so the
  parse adds about 42 B.
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

import math
import os
import re
from pathlib import Path

import numpy as np

from .errors import DataFileError
from .sizes import available_memory, human_bytes

__all__ = [
    "CSV_PARSE_BYTES_PER_SAMPLE",
    "DEGRADE_BYTES_PER_SAMPLE",
    "FEATURES_BYTES_PER_SAMPLE",
    "TWIN_BYTES_PER_IDE_BYTE",
    "TWIN_BYTES_PER_SAMPLE",
    "check_parse_size",
    "file_samples",
]

#: peak bytes per input sample of ``sdt degrade`` (.npy; a CSV adds CSV_PARSE_BYTES_PER_SAMPLE)
DEGRADE_BYTES_PER_SAMPLE = 40
#: peak bytes per value of parsing a CSV signal (read_csv_signal), on top of the command's
CSV_PARSE_BYTES_PER_SAMPLE = 48
#: peak bytes per input sample of ``sdt features extract``
FEATURES_BYTES_PER_SAMPLE = 44
#: peak bytes per value (both files of a TOML pair, any time column counted) of ``twin check``
TWIN_BYTES_PER_SAMPLE = 80
#: peak bytes per byte of an IDE file of ``sdt twin check``
TWIN_BYTES_PER_IDE_BYTE = 64

_HEAD = 65_536  # bytes of a CSV read to measure its lines
_SEPARATORS = re.compile(r"[,;\t ]+")


def _npy_samples(path: Path) -> int | None:
    with path.open("rb") as handle:
        version = np.lib.format.read_magic(handle)
        read = {
            (1, 0): np.lib.format.read_array_header_1_0,
            (2, 0): np.lib.format.read_array_header_2_0,
        }.get(version)
        if read is None:
            return None
        shape = read(handle)[0]
    return math.prod(shape)


def _is_number(token: str) -> bool:
    try:
        float(token)
    except ValueError:
        return False
    return True


def _csv_samples(path: Path) -> int | None:
    """Values in a CSV: its size over the mean length of the first data lines, times columns."""
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


def _mat_samples(path: Path, variable: str | None) -> int | None:
    from scipy.io import whosmat

    found = [(name, shape) for name, shape, _ in whosmat(str(path))]
    if variable is not None:
        found = [(name, shape) for name, shape in found if name == variable]
    return sum(math.prod(shape) for _, shape in found) or None


def file_samples(path: str | os.PathLike[str], variable: str | None = None) -> int | None:
    """Values stored in the signal file at ``path`` (.npy, .csv, .mat), from its header.

    A CSV's count is an estimate (its size over its first lines' length). None
    when the file cannot be sized this way (missing, unknown type, damaged
    header): reading it then reports what is wrong.
    """
    path = Path(path)
    suffix = path.suffix.lower()
    try:
        if not path.is_file():
            return None
        if suffix == ".npy":
            return _npy_samples(path)
        if suffix == ".csv":
            return _csv_samples(path)
        if suffix == ".mat":
            return _mat_samples(path, variable)
    except (OSError, ValueError, EOFError, TypeError, NotImplementedError):
        return None
    return None


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
