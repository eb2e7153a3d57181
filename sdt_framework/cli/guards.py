"""Checks a command makes before its work, and the one line an OS error becomes.

- :func:`check_output_file`: an output path is refused before any computation
  when its extension is not offered, it is a folder, it is (or resolves to) an
  input file, or its folder cannot be written (probed with a nameless
  temporary file, so a read-only mount is caught even for root).
- :func:`os_errors`: any ``OSError`` left (disk full mid-write, a file removed
  under our feet) becomes an :class:`~sdt_framework.errors.SDTError` naming the
  path and what to do; ``sdt_framework.io`` has already removed the
  half-written temporary file.
- :func:`check_cost`: a size that cannot fit in this machine's memory (or
  disk) is refused; one that is large or long needs ``--yes``.
- :func:`check_memory`: one input file whose samples cannot fit in the memory
  available is refused before it is read.

The overwrite rule, one for every command that writes a file the user names
(``degrade --out``, ``features extract --out``, ``validate-noise --plot``,
``twin check --plot``, ``twin fit --out``): an existing file is refused,
naming it, unless ``--overwrite`` is given (the flag of ``sdt dataset
synth``, :data:`OVERWRITE_HELP`); an input file is never an output,
``--overwrite`` or not.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import tempfile
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import SDTError

if TYPE_CHECKING:
    from ..signals import Cost

__all__ = [
    "DISK_SHARE",
    "LONG_SECONDS",
    "MEMORY_SHARE",
    "OVERWRITE_HELP",
    "check_cost",
    "check_memory",
    "check_output_file",
    "check_output_folder",
    "describe_os_error",
    "os_errors",
    "same_file",
]

#: above this estimated run time a command asks for --yes
LONG_SECONDS = 600.0
#: above this share of the available memory (or free disk) a command asks for --yes
MEMORY_SHARE = 0.5
DISK_SHARE = 0.5
#: the help of every command's ``--overwrite`` (the overwrite rule above)
OVERWRITE_HELP = "Replace the output file if it exists (an input file is never replaced)."

_ADVICE = {
    errno.ENOENT: "check the path",
    errno.EACCES: "choose a folder you can write to, or fix its permissions",
    errno.EPERM: "choose a folder you can write to, or fix its permissions",
    errno.EROFS: "the file system is read-only; choose another folder",
    errno.ENOSPC: "the disk is full; free space or choose another folder",
    errno.EISDIR: "it is a folder; give a file path",
    errno.ENOTDIR: "a part of the path is a file, not a folder; choose another path",
}
if hasattr(errno, "EDQUOT"):  # POSIX only
    _ADVICE[errno.EDQUOT] = "the disk quota is used up; free space or choose another folder"
_TEMPORARY = re.compile(r"^\.(?P<name>.+)\.[^.]+\.tmp$")  # sdt_framework.io's temporary names


def _shown(filename: object) -> str:
    """The path to name: a temporary file of ``sdt_framework.io`` as its destination."""
    path = Path(str(filename))
    match = _TEMPORARY.match(path.name)
    return str(path.with_name(match["name"])) if match else str(path)


def describe_os_error(exc: OSError, fallback: str = "") -> str:
    """One line for an OS error: the path, what happened, what to do."""
    path = _shown(exc.filename) if exc.filename is not None else fallback
    known = os.strerror(exc.errno) if exc.errno else type(exc).__name__  # an OutputError
    what = (exc.strerror or known).lower()
    advice = _ADVICE.get(exc.errno or 0, "check the path and try again")
    return f"{path or '(no path)'}: {what}; {advice}"


@contextlib.contextmanager
def os_errors(fallback: str = "") -> Iterator[None]:
    """Turn any ``OSError`` raised inside into a one-line :class:`SDTError`."""
    try:
        yield
    except OSError as exc:
        raise SDTError(describe_os_error(exc, fallback)) from None


def same_file(a: Path, b: Path) -> bool:
    """Whether two paths name one file (relative paths, ``..``, symlinks, hard links)."""
    if os.path.realpath(a) == os.path.realpath(b):
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _probe_folder(folder: Path, option: str, path: Path) -> None:
    """``folder`` (where ``path`` will be written) exists or can be made, and is writable."""
    folder = Path(os.path.abspath(folder))
    while not folder.exists():
        folder = folder.parent
    if not folder.is_dir():
        raise SDTError(f"{option} {path}: {folder} is a file, not a folder; choose another path")
    try:
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as exc:
        what = (exc.strerror or type(exc).__name__).lower()
        raise SDTError(
            f"{option} {path}: cannot write in {folder} ({what}); choose a writable folder"
        ) from None


def check_output_file(
    path: Path,
    option: str,
    suffixes: Sequence[str],
    inputs: Sequence[Path] = (),
    *,
    overwrite: bool,
) -> None:
    """Refuse an output file path before any work is done (the overwrite rule above).

    Parameters
    ----------
    path
        The path the user named.
    option
        How the user named it (``--out``), quoted in the message.
    suffixes
        Extensions offered, with the dot (``.npy``).
    inputs
        Files the command reads: the output may not be one of them.
    overwrite
        The user's ``--overwrite``: without it an existing file is refused.
    """
    if path.is_dir():
        example = path / f"out{suffixes[0]}"
        raise SDTError(f"{option} {path} is a folder; give a file path such as {example}")
    suffix = path.suffix.lower()
    if suffix not in suffixes:
        raise SDTError(
            f"{option} {path}: unsupported extension {suffix or '(none)'!r}; "
            f"use one of {', '.join(suffixes)}"
        )
    for source in inputs:
        if same_file(path, source):
            raise SDTError(
                f"{option} {path} is the input file {source}; write to another path "
                f"(an input is never overwritten)"
            )
    if not overwrite and os.path.lexists(path):
        raise SDTError(
            f"{option} {path} exists; choose a new file, or pass --overwrite to replace it"
        )
    _probe_folder(path.parent, option, path)


def check_output_folder(path: Path, option: str) -> None:
    """Refuse an output folder that is a file or cannot be created or written."""
    if path.exists() and not path.is_dir():
        raise SDTError(f"{option} {path} is a file; give a folder")
    _probe_folder(path, option, path)


def check_cost(what: str, cost: Cost, yes: bool, reduce: str, folder: Path | None = None) -> None:
    """Refuse a size this machine cannot hold; ask for ``--yes`` before a large or long one.

    ``reduce`` says which options make it smaller; ``folder`` is where its disk
    output goes.
    """
    from ..signals import available_memory, free_disk, human_bytes, human_seconds

    memory, disk, seconds, samples = cost.memory_bytes, cost.disk_bytes, cost.seconds, cost.samples
    room = available_memory()
    free = free_disk(folder) if folder is not None and disk else None
    size = f"{samples:,} samples, about {human_bytes(memory)} of memory"
    if disk:
        size += f" and {human_bytes(disk)} on disk"
    if memory > room:
        raise SDTError(
            f"{what}: {size}: more than the {human_bytes(room)} of memory available; "
            f"reduce {reduce}"
        )
    if free is not None and disk > free:
        raise SDTError(
            f"{what}: {size}: more than the {human_bytes(free)} free on disk; reduce {reduce}"
        )
    large = memory > MEMORY_SHARE * room or (free is not None and disk > DISK_SHARE * free)
    if (large or seconds > LONG_SECONDS) and not yes:
        raise SDTError(
            f"{what}: {size}, estimated {human_seconds(seconds)}; "
            f"pass --yes to run it, or reduce {reduce}"
        )


def check_memory(path: Path, size: str, memory: int, advice: str) -> None:
    """Refuse ``path`` before reading it when its ``size`` ("N samples") needs more
    ``memory`` (bytes) than is available now (memory, cgroup and ``ulimit -v`` limits);
    ``advice`` says what to do instead."""
    from ..signals import available_memory, human_bytes

    room = available_memory()
    if memory > room:
        raise SDTError(
            f"{path}: {size} need about {human_bytes(memory)} of memory, more than "
            f"the {human_bytes(room)} available; {advice}"
        )
