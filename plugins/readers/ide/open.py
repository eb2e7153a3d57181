"""Open an enDAQ IDE file through idelib, and refuse one it could read only in part.

idelib stops at the first element it cannot parse (a damaged block, a cut
file) and returns what it read so far, setting ``fileDamaged``; a file cut
inside a data block makes it raise instead. Read silently, a damaged file is a
shorter recording with a different verdict. So:

- a file that **ends inside its last element** (a copy or a recording cut
  short) is read up to that element, with a note naming the byte where the file
  ends and the seconds read;
- a file **damaged before its end** is refused, naming the byte where idelib
  stopped reading and the seconds of samples it had read: the samples before
  the damage may be damaged too, and nothing says which.

A path that is missing, a folder, a device or a pipe is named as such. Text
fields holding non-ASCII bytes (channel names) are read with replacement
characters and one note, instead of ebmlite's raw warning. EBML parsing is
idelib's and ebmlite's; here only their results are compared with the file.
"""

from __future__ import annotations

import io
import os
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sdt_framework.errors import SDTError
from sdt_framework.inputs import require_regular_file

__all__ = ["OpenedIde", "open_ide"]

#: an EBML element header is at most this long (an ID of 4 bytes, a size of 8)
HEADER_BYTES = 12


@dataclass(frozen=True)
class OpenedIde:
    """An imported idelib ``Dataset`` and what to tell the user about how it was read."""

    doc: Any
    notes: tuple[str, ...]


def _require_file(path: Path) -> None:
    if path.is_dir():
        raise SDTError(f"{path}: is a folder, not an IDE file; give the .IDE recording itself")
    require_regular_file(path, "IDE file")
    if not path.exists():
        raise SDTError(f"{path}: no such IDE file; check the path")


def _import(source: Any) -> tuple[Any | None, list[warnings.WarningMessage]]:
    """(idelib Dataset, None if not even its header could be read, warnings raised meanwhile).
    A Dataset whose data raised part-way is marked ``fileDamaged``, as idelib marks the ones
    it stops reading itself."""
    from idelib.importer import openFile, readData  # heavy: on use only

    doc = None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            doc = openFile(source, quiet=True)
            readData(doc)
        except Exception:  # any failure of the reader: a damaged file
            if doc is not None:
                doc.fileDamaged = True
    return doc, list(caught)


def _seconds(doc: Any) -> float:
    """Time of the last sample read, over every channel, s (0 when none was read)."""
    ends = [
        float(ch.getSession()[-1][0]) * 1e-6 for ch in doc.channels.values() if len(ch.getSession())
    ]
    return max(ends, default=0.0)


def _stop(doc: Any) -> int:
    """The byte after the last data block idelib read (0 when it read none)."""
    ends = [0]
    for ch in doc.channels.values():
        blocks = getattr(ch.getSession(), "_data", None) or []
        element = getattr(blocks[-1], "element", None) if blocks else None
        if element is not None:
            ends.append(int(element.payloadOffset) + int(element.size))
    return max(ends)


def _cut_at(path: Path, size: int) -> int | None:
    """Offset of the incomplete element the file ends in, or None if it does not end in one
    (top-level elements, read by ebmlite; a damaged element before the end gives None)."""
    from idelib.importer import openFile

    end = 0
    with open(path, "rb") as stream, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            for element in openFile(stream, quiet=True).ebmldoc:
                if int(element.payloadOffset) + int(element.size) > size:
                    return int(element.offset)
                end = int(element.payloadOffset) + int(element.size)
        except Exception:  # a header cut by the end of the file, or damage
            return end if size - end <= HEADER_BYTES else None
    return None


def _notes(caught: list[warnings.WarningMessage]) -> tuple[str, ...]:
    if any(issubclass(w.category, UnicodeWarning) for w in caught):
        return (
            "some names in the file are not ASCII text; their other bytes are shown as '\ufffd'",
        )
    return ()


def open_ide(path: str | os.PathLike[str]) -> OpenedIde:
    """The IDE file at ``path`` imported in full, or up to the element it is cut in (noted);
    a damaged file is refused naming where reading stopped."""
    path = Path(path)
    _require_file(path)
    size = path.stat().st_size
    stream = open(path, "rb")  # noqa: SIM115 - the Dataset keeps it, and closes it
    doc, caught = _import(stream)
    if doc is not None and not doc.fileDamaged:
        return OpenedIde(doc, _notes(caught))
    try:
        stop, seconds = (_stop(doc), _seconds(doc)) if doc is not None else (0, 0.0)
    except Exception:  # a Dataset left half-built by the reader: where it stopped is unknown
        stop, seconds = 0, 0.0
    stream.close()
    cut = _cut_at(path, size)
    if cut is not None:
        with open(path, "rb") as stream:
            head, caught = _import(io.BytesIO(stream.read(cut)))
        if head is not None and not head.fileDamaged and head.channels:
            note = (
                f"{path.name}: truncated: the file ends at byte {size:,} inside an element "
                f"that starts at byte {cut:,}; read the {cut:,} bytes before it (samples to "
                f"{_seconds(head):.3f} s)"
            )
            return OpenedIde(head, (*_notes(caught), note))
    if stop == 0:
        raise SDTError(
            f"{path}: not a readable enDAQ IDE file (idelib could not parse it); give a .IDE "
            f"recording written by an enDAQ or Slam Stick recorder"
        )
    raise SDTError(
        f"{path}: damaged: idelib stopped reading at byte {stop:,} of {size:,} "
        f"({stop / size:.0%}), after {seconds:.3f} s of samples; the rest of the file is not "
        f"readable and the samples before may be damaged too, so it is not used; copy the "
        f"file from the recorder again"
    )
