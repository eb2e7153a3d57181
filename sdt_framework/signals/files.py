"""Find the reader of a signal file among the registered ones, and read through it.

Readers are plugins (:class:`~sdt_framework.specs.ReaderSpec`, hook
``register_signal_readers``): CSV, NPY, MATLAB v5 and v7.3, enDAQ IDE, TDMS,
UFF58, WAV and LabVIEW LVM are built in and registered through the same entry
points as a third party's. A file's reader is chosen by suffix; where several
readers share a suffix (``.mat``: v5 and v7.3) or a file has none of the known
suffixes, by each reader's ``sniff`` of the file's first bytes. A file no
reader recognises is refused naming the formats that are.

This layer sits below the registry, so the table of readers is handed down:
every function here takes ``readers`` (``registry.signal_readers()``, as
xarray's ``guess_engine`` asks the engines ``list_engines`` gives it); nothing
here looks a registry up, and nothing installs one. A manifest resolves each
row's reader when it is opened and keeps the reader's ``read`` function, so a
worker process never needs the registry.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from .errors import DataFileError
from .rules import SignalInfo, fault_of
from .tokens import brief

__all__ = [
    "SNIFF_BYTES",
    "channel_reader",
    "known_formats",
    "read_signal",
    "reader_for",
    "scan_file",
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


def reader_for(file: str | Path, readers: Sequence[Any]) -> Any:
    """The reader of ``file`` among ``readers`` (``ReaderSpec``, handed down by the caller):
    by suffix, then by sniffing the first bytes; else refused."""
    file = Path(file)
    readers = list(readers)
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


def channel_reader(file: str | Path, readers: Sequence[Any]) -> Any | None:
    """The reader of ``file`` if its format holds channels (``ReaderSpec.channels``: an IDE
    file), else None: also when no reader recognises the file or it cannot be read, which
    reading it then says."""
    try:
        reader = reader_for(file, readers)
    except DataFileError:
        return None
    return reader if reader.channels is not None else None


def scan_file(
    file: str | Path, readers: Sequence[Any], **options: Any
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


def read_signal(
    file: str | Path, readers: Sequence[Any], variable: str | None = None, **options: Any
) -> np.ndarray:
    """The samples of the signal ``variable`` of ``file`` (None: its only one) as float64
    (n_acquisitions, n_samples), all finite, through its reader among ``readers``."""
    return reader_for(file, readers).read(Path(file), variable, **options)
