"""Atomic file output: a results file is either complete or absent.

Writers produce a temporary file in the destination folder and rename it into
place (``os.replace`` is atomic on POSIX and Windows), so an interrupted run
never leaves a half-written file behind. An OS error while writing (disk full,
read-only folder, a file where a folder should be) removes the temporary file
and becomes an :class:`OutputError`: one line naming the path and what to do,
still an ``OSError`` for callers that tolerate a failed write (a cache).

A writer whose file name comes from data (a figure named after a machine)
passes ``root``, the folder the user named: a destination that resolves
outside it (``..``, an absolute name, a symbolic link below ``root`` leading
out) is refused before any folder is created.
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path

from .errors import SDTError

__all__ = [
    "OutputError",
    "atomic_path",
    "atomic_write_bytes",
    "atomic_write_text",
    "ensure_writable_dir",
    "inside",
    "os_error_hint",
]


class OutputError(SDTError, OSError):
    """A file or folder that cannot be written (an ``SDTError`` and an ``OSError``)."""


def os_error_hint(exc: OSError) -> str:
    """What a user can do about ``exc``, in a few words."""
    if exc.errno in (errno.ENOSPC, errno.EDQUOT):
        return "free some disk space or choose a folder on another disk"
    if exc.errno in (errno.EACCES, errno.EPERM, errno.EROFS):
        return "choose a folder you can write to"
    if exc.errno in (errno.ENOTDIR, errno.EEXIST):
        return "a file stands where a folder is needed; choose another path"
    return "check the path and the disk"


def _output_error(path: Path, exc: OSError) -> OutputError:
    error = OutputError(f"cannot write {path}: {exc.strerror or exc}; {os_error_hint(exc)}")
    error.errno = exc.errno
    return error


def _ours(exc: OSError, *paths: Path) -> bool:
    """Whether ``exc`` concerns one of ``paths`` (or no file at all: a write to a handle)."""
    return exc.filename is None or Path(exc.filename) in paths


def inside(root: str | os.PathLike[str], destination: str | os.PathLike[str]) -> Path:
    """``destination`` if it resolves to a path strictly inside the folder ``root``.

    Both are resolved (symbolic links followed, ``..`` removed), so a name
    holding ``../`` or a link below ``root`` pointing elsewhere cannot lead out.

    Raises
    ------
    OutputError
        When it would not lie inside ``root``.
    """
    destination = Path(destination)
    base, target = Path(root).resolve(), destination.resolve()
    if target == base or not target.is_relative_to(base):
        raise OutputError(
            f"refusing to write {destination}: it resolves to {target}, outside the output "
            f"folder {base}; a file name must not lead out of the folder it is written to"
        )
    return destination


@contextlib.contextmanager
def atomic_path(
    destination: str | os.PathLike[str], *, root: str | os.PathLike[str] | None = None
) -> Iterator[Path]:
    """Yield a temporary path beside ``destination``; rename it there on success.

    With ``root``, ``destination`` must resolve inside that folder (:func:`inside`).

    Raises
    ------
    OutputError
        When ``destination`` is outside ``root``, or the folder cannot be
        created or the file cannot be written; the temporary file is removed
        and ``destination`` is left as it was.
    """
    destination = Path(destination) if root is None else inside(root, destination)
    try:
        destination.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(
            prefix=f".{destination.name}.", suffix=".tmp", dir=destination.parent
        )
    except OSError as exc:
        raise _output_error(destination, exc) from None
    os.close(fd)
    tmp_path = Path(tmp)
    # mkstemp creates 0600; give the result the permissions a plain open() would.
    umask = os.umask(0)
    os.umask(umask)
    try:
        os.chmod(tmp_path, 0o666 & ~umask)
        yield tmp_path
        os.replace(tmp_path, destination)
    except OSError as exc:
        if isinstance(exc, OutputError) or not _ours(exc, tmp_path, destination):
            raise
        raise _output_error(destination, exc) from None
    finally:
        tmp_path.unlink(missing_ok=True)


def atomic_write_bytes(
    destination: str | os.PathLike[str], data: bytes, *, root: str | os.PathLike[str] | None = None
) -> None:
    """Write ``data`` to ``destination`` atomically (inside ``root``, if given)."""
    with atomic_path(destination, root=root) as tmp:
        tmp.write_bytes(data)


def atomic_write_text(
    destination: str | os.PathLike[str], text: str, *, root: str | os.PathLike[str] | None = None
) -> None:
    """Write UTF-8 ``text`` to ``destination`` atomically (inside ``root``, if given)."""
    atomic_write_bytes(destination, text.encode("utf-8"), root=root)


def ensure_writable_dir(path: str | os.PathLike[str], what: str, option: str) -> Path:
    """Create ``path`` if needed and prove it writable, before any work depends on it.

    ``what`` names the folder's role and ``option`` how to choose another one
    (e.g. ``"--cache-dir or SDT_CACHE_DIR"``); both appear in the error.
    """
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise OutputError(f"{what} {path} is a file, not a folder; choose a folder with {option}")
    try:
        path.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=path):
            pass
    except OSError as exc:
        raise OutputError(
            f"cannot write the {what} {path}: {exc.strerror or exc}; choose another with {option}"
        ) from None
    return path
