"""Every file below a folder, symbolic links followed safely, and every entry not used with why.

``sdt dataset manifest`` reads a campaign's folder tree, where run folders are
often symbolic links to another disk and a copy may leave a broken link or a
named pipe. :func:`walk_tree` lists the regular files under the folder in
path order, following linked folders and files, and returns every other
entry with the reason it is not used, never dropping one silently:

- the real tree is listed first, then each symbolic link in path order, so a
  file or folder reached both directly and through a link is used once, at
  its real place, and the link is named ("the same folder as ...");
- a link to a folder above it (a loop), or to a folder already listed, is not
  followed; nothing outside the folder is read unless a link in it points there;
- a broken link, a FIFO, a socket or a device (never opened: reading a FIFO
  blocks, a device may never end) and a folder that cannot be listed are
  named with the reason.
"""

from __future__ import annotations

import errno
import os
import stat
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from ..inputs import not_regular

__all__ = ["TreeFiles", "walk_tree"]


@dataclass
class TreeFiles:
    """Regular files as (path below the folder, path to open), and entries not used with why."""

    files: list[tuple[PurePosixPath, Path]] = field(default_factory=list)
    left_out: list[tuple[str, str]] = field(default_factory=list)


@dataclass
class _Walk:
    found: TreeFiles
    seen: dict[tuple[int, int], str]  # (device, inode) -> where it was first listed
    links: list[tuple[PurePosixPath, Path, tuple[tuple[int, int], ...]]]


def _key(status: os.stat_result) -> tuple[int, int]:
    return status.st_dev, status.st_ino


def _list(walk: _Walk, below: PurePosixPath, path: Path, above: tuple[tuple[int, int], ...]):
    """List one real folder: files and folders now, symbolic links for later."""
    try:
        entries = sorted(os.scandir(path), key=lambda e: e.name)
    except OSError as exc:
        walk.found.left_out.append((f"{below}/", f"folder cannot be listed ({exc.strerror})"))
        return
    for entry in entries:
        where = below / entry.name
        if entry.is_symlink():
            walk.links.append((where, Path(entry.path), above))
            continue
        try:
            status = entry.stat(follow_symlinks=False)
        except OSError as exc:
            walk.found.left_out.append((str(where), f"cannot be read ({exc.strerror})"))
            continue
        _add(walk, where, Path(entry.path), status, above)


def _add(walk: _Walk, where, path: Path, status: os.stat_result, above) -> None:
    """One entry (a link already resolved to ``status``): file, folder, or left out."""
    key = _key(status)
    if stat.S_ISDIR(status.st_mode):
        if key in above:
            walk.found.left_out.append(
                (f"{where}/", "symbolic link to a folder above it (a loop); not followed")
            )
        elif key in walk.seen:
            walk.found.left_out.append(
                (f"{where}/", f"the same folder as {walk.seen[key]}; its files are used there")
            )
        else:
            walk.seen[key] = f"{where}/"
            _list(walk, where, path, (*above, key))
    elif stat.S_ISREG(status.st_mode):
        if key in walk.seen:
            walk.found.left_out.append((str(where), f"the same file as {walk.seen[key]}"))
        else:
            walk.seen[key] = str(where)
            walk.found.files.append((where, path))
    else:
        kind = not_regular(path) or "not a file"
        walk.found.left_out.append((str(where), f"not a regular file ({kind}); not opened"))


def walk_tree(folder: Path) -> TreeFiles:
    """Files below ``folder`` (a folder) and the entries left out, each in path order."""
    root = os.stat(folder)
    walk = _Walk(TreeFiles(), {_key(root): "./"}, [])
    _list(walk, PurePosixPath(), folder, (_key(root),))
    while walk.links:
        walk.links.sort(key=lambda link: link[0].parts)
        where, path, above = walk.links.pop(0)
        try:
            status = os.stat(path)  # follows the link
        except OSError as exc:
            target = os.readlink(path)
            why = (
                f"broken symbolic link to {target} (target missing)"
                if exc.errno == errno.ENOENT
                else f"symbolic link to {target} cannot be followed ({exc.strerror})"
            )
            walk.found.left_out.append((str(where), why))
            continue
        _add(walk, where, path, status, above)
    walk.found.files.sort(key=lambda item: item[0].parts)
    walk.found.left_out.sort()
    return walk.found
