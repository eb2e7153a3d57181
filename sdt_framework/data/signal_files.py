"""Find the reader of a signal file among the registered ones, and read through it.

Readers are plugins (:class:`~sdt_framework.specs.ReaderSpec`, hook
``register_signal_readers``): CSV, NPY, MATLAB v5 and v7.3, enDAQ IDE, TDMS,
UFF58, WAV and LabVIEW LVM are built in and registered through the same entry
points as a third party's. A file's reader is chosen by suffix; where several
readers share a suffix (``.mat``: v5 and v7.3) or a file has none of the known
suffixes, by each reader's ``sniff`` of the file's first bytes. A file no
reader recognises is refused naming the formats that are.

The data layer sits below the registry, so the readers table is handed down:
a caller passes ``readers``, or :mod:`sdt_framework.registry` installs the
default registry's table when imported (:mod:`sdt_framework.reader_table`).
A manifest resolves each row's reader when it is opened and keeps the
reader's ``read`` function, so a worker process never needs the registry.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ..reader_table import reader_table
from .readers import SignalInfo, fault_of
from .recording import DataFileError
from .tokens import brief

__all__ = [
    "SNIFF_BYTES",
    "known_formats",
    "probe_signal",
    "read_signal",
    "reader_for",
    "scan_file",
    "signal_shape",
]

#: how many leading bytes of a file a reader's ``sniff`` sees
SNIFF_BYTES = 1024


def _head(file: Path) -> bytes:
    try:
        with open(file, "rb") as handle:
            return handle.read(SNIFF_BYTES)
    except OSError as exc:
        raise DataFileError(f"{file}: cannot read ({exc.strerror or brief(exc)})") from None


def _sniffs(reader: Any, head: bytes) -> bool:
    try:
        return bool(reader.sniff(head))
    except Exception:  # a plugin's sniff failing on odd bytes: it does not claim the file
        return False


def known_formats(readers: Sequence[Any]) -> str:
    """``CSV (.csv), NPY (.npy), ...``: every registered format, for messages."""
    return ", ".join(f"{r.label} ({', '.join(r.suffixes)})" for r in readers)


def reader_for(file: str | Path, readers: Sequence[Any] | None = None) -> Any:
    """The reader of ``file``: by suffix, then by sniffing the first bytes; else refused."""
    file = Path(file)
    readers = reader_table() if readers is None else list(readers)
    suffix = file.suffix.lower()
    by_suffix = [r for r in readers if suffix in r.suffixes]
    if len(by_suffix) == 1 and by_suffix[0].sniff is None:
        return by_suffix[0]
    head = _head(file)
    pool = by_suffix or [r for r in readers if r.sniff is not None]
    claimed = [r for r in pool if r.sniff is not None and _sniffs(r, head)]
    if claimed:
        return claimed[0]
    unsniffed = [r for r in by_suffix if r.sniff is None]
    if unsniffed:
        return unsniffed[0]
    if by_suffix:
        labels = " or ".join(r.label for r in by_suffix)
        raise DataFileError(
            f"{file}: named {suffix} but its first bytes are not those of a {labels} file "
            f"({len(head)} bytes read); check the file (a copy cut short, another format)"
        )
    raise DataFileError(
        f"{file}: format not recognised (suffix {suffix or '(none)'!r}); sdt reads "
        f"{known_formats(readers)}; a reader plugin adds others"
    )


def scan_file(
    file: str | Path, readers: Sequence[Any] | None = None, **options: Any
) -> tuple[Any, list[SignalInfo]]:
    """(reader, every signal of ``file``) for ``sdt dataset inspect FILE``; a file none of
    whose signals can be read (each has a fault: a header rate of 0 Hz, no samples) is
    refused with the first signal's fault."""
    reader = reader_for(file, readers)
    infos = list(reader.scan(Path(file), **options))
    faults = [fault_of(Path(file), info) for info in infos]
    if infos and all(faults):
        raise DataFileError(str(faults[0]))
    return reader, infos


def probe_signal(
    file: Path, variable: str | None, readers: Sequence[Any] | None = None, **options: Any
) -> tuple[Any, SignalInfo]:
    """(reader, the signal a manifest row names), reading as little as the format allows."""
    reader = reader_for(file, readers)
    return reader, reader.probe(Path(file), variable, **options)


def signal_shape(file: Path, variable: str | None) -> tuple[tuple[int, int], str | None]:
    """((n_acquisitions, n_samples), note) of a signal file, through its reader."""
    info = probe_signal(file, variable)[1]
    return info.shape, info.note


def read_signal(file: Path, variable: str | None, **options: Any) -> np.ndarray:
    """The samples of a signal file as float64 (n_acquisitions, n_samples), all finite."""
    return reader_for(file).read(Path(file), variable, **options)
