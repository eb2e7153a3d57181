"""One benchmark at a time per results folder: a lock held while it runs.

Two ``sdt benchmark --out SAME`` started together used to compute everything
twice, each overwriting the other's files. The first to claim the folder now
holds an exclusive ``flock`` on ``<out>/.sdt-lock`` (the file holds its
process id, to name it); a second process is refused with one line naming the
folder and that process. The kernel drops the lock when its process ends,
however it ends (SIGKILL, power loss included), so a lock file left by a killed
benchmark is simply taken over: no stale-lock guessing. The file itself stays
(removing it would let a third process lock a new file while a second still
holds the old one).

Locks are per process and re-entrant: the command claims its folder, and
:func:`~sdt_framework.bench.runner.run_benchmark` claims it again. On a
platform without ``fcntl`` (Windows) folders are not locked.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import SDTError

try:
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None  # type: ignore[assignment]

__all__ = ["LOCK", "holds_results_folder", "lock_results_folder", "unlock_results_folder"]

LOCK = ".sdt-lock"

#: folder (resolved) -> descriptor of its lock file, for the folders this process holds
_held: dict[str, int] = {}


def _key(out: Path) -> str:
    return str(Path(out).resolve())


def holds_results_folder(out: str | os.PathLike[str]) -> bool:
    """Whether this process holds the lock of ``out``."""
    return _key(Path(out)) in _held


def lock_results_folder(out: str | os.PathLike[str]) -> None:
    """Hold ``out``'s lock from now on (``out`` exists); a no-op when held already.

    Raises
    ------
    SDTError
        Another running process holds it (named by its process id).
    """
    key = _key(Path(out))
    if key in _held or fcntl is None:
        return
    path = Path(out) / LOCK
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        owner = os.pread(fd, 64, 0).decode("ascii", "replace").strip() or "unknown"
        os.close(fd)
        raise SDTError(
            f"--out {out} is in use by another sdt benchmark (process {owner}); wait for it "
            f"to finish (then run the same command to resume), or choose another --out"
        ) from None
    except OSError:
        os.close(fd)
        raise
    os.ftruncate(fd, 0)
    os.pwrite(fd, f"{os.getpid()}\n".encode(), 0)
    _held[key] = fd


def unlock_results_folder(out: str | os.PathLike[str]) -> None:
    """Release ``out``'s lock if this process holds it."""
    fd = _held.pop(_key(Path(out)), None)
    if fd is not None:
        os.close(fd)  # closing the descriptor releases its flock
