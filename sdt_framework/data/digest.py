"""The content digest of a data file: what the caches key a recording's file by.

Keying by path, size and modification time served stale features: a corrected
DAQ export of the same size copied over the old one with its mtime kept (``cp
-p``, ``rsync -a``) was taken for the old file, and a fresh cache changed 83 %
of the Macro F1 values. A file is now known by a SHA-256 of its bytes, read in
1 MiB blocks (``hashlib.file_digest``; SHA-256 runs at about 1.6 GB/s on the
reference machine with its SHA extensions, faster than most disks deliver).

Hashing every file at every run would read an 80 GB archive whose features are
all cached, so each digest is remembered in the cache folder under the file's
identity: path, device, inode, size, modification time and change time. The
change time (ctime) is set by the kernel whenever a file's data or metadata
change and cannot be set back (``cp -p`` and ``touch -d`` restore the mtime,
never the ctime; ``rsync -a`` writes a new inode), so any rewrite makes the
file hash again. As Git does for its index, a digest taken within
:data:`SETTLE_NS` of the file's last change is not remembered: a second write
in the same clock tick (on a file system with coarse timestamps) could keep
the identity and change the bytes.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import re
import time
from pathlib import Path

from ..io import atomic_write_text

__all__ = ["SETTLE_NS", "file_digest"]

#: a digest is remembered only once the file is this old (ns since its last change)
SETTLE_NS = 2_000_000_000
_HEX = re.compile(r"[0-9a-f]{64}")


def _identity(path: str, stat: os.stat_result) -> str:
    fields = (path, stat.st_dev, stat.st_ino, stat.st_size, stat.st_mtime_ns, stat.st_ctime_ns)
    return hashlib.sha256("\x1f".join(map(str, fields)).encode()).hexdigest()


def _hash(path: str) -> str:
    with open(path, "rb") as handle:
        return hashlib.file_digest(handle, "sha256").hexdigest()


def file_digest(path: str | os.PathLike[str], memo_dir: str | os.PathLike[str] | None) -> str:
    """SHA-256 (hex) of the bytes of ``path``, remembered under ``memo_dir/digests``.

    ``memo_dir`` None hashes every time. An unreadable or damaged memo entry
    is hashed again; a memo that cannot be written is not needed.

    Raises
    ------
    OSError
        ``path`` cannot be read.
    """
    real = os.path.realpath(path)
    stat = os.stat(real)
    if memo_dir is None:
        return _hash(real)
    identity = _identity(real, stat)
    memo = Path(memo_dir) / "digests" / identity[:2] / identity
    try:
        known = memo.read_text(encoding="ascii").strip()
        if _HEX.fullmatch(known):
            return known
    except (OSError, ValueError):
        pass
    digest = _hash(real)
    settled = time.time_ns() - max(stat.st_mtime_ns, stat.st_ctime_ns) > SETTLE_NS
    if settled and _identity(real, os.stat(real)) == identity:  # unchanged while read
        with contextlib.suppress(OSError):  # a memo that cannot be written is not needed
            atomic_write_text(memo, digest + "\n")
    return digest
