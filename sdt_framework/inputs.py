"""Input paths that exist but are not files: refused before they are read.

A device, a named pipe or a socket given where a file is expected
(``/dev/zero`` as a sensor file, a config, a sweep, an allocation table or a
signal, or a manifest line pointing at one) would be read until memory runs
out, or block forever. Every reader of a user-named file asks
:func:`require_regular_file` first, so such a path is one line naming it and
what it is. A missing path or a folder is left to the reader's own message.
"""

from __future__ import annotations

import os
import stat

from .errors import SDTError

__all__ = ["not_regular", "require_regular_file"]

_KINDS = (
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISFIFO, "a named pipe"),
    (stat.S_ISSOCK, "a socket"),
)


def not_regular(path: str | os.PathLike[str]) -> str | None:
    """What ``path`` is if it exists and is neither a regular file nor a folder, else None."""
    try:
        mode = os.stat(path).st_mode  # follows symlinks: a link to /dev/zero is a device
    except (OSError, ValueError):
        return None
    if stat.S_ISREG(mode) or stat.S_ISDIR(mode):
        return None
    return next((kind for test, kind in _KINDS if test(mode)), "not a file")


def require_regular_file(path: str | os.PathLike[str], what: str) -> None:
    """Refuse ``path`` (named as ``what``, e.g. ``sensor file``) if it is a device or pipe."""
    kind = not_regular(path)
    if kind is not None:
        raise SDTError(
            f"{what} {os.fsdecode(path)}: not a regular file ({kind}); give the path of a file"
        )
