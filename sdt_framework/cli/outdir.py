"""Where ``sdt compare`` and ``sdt report`` write: the results folder, or ``--out``.

Both read a results folder and by default write into it. A folder the user
cannot write (a colleague's, a read-only mount, an archive) is still read;
the output then goes where ``--out`` says, and without ``--out`` the command
stops before any work with one line saying so, instead of failing at the
first file it writes.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import SDTError
from ..io import OutputError, ensure_writable_dir

__all__ = ["output_folder"]


def output_folder(results_dir: Path, out: Path | None, what: str) -> Path:
    """The folder ``what`` (e.g. "the comparison table") is written to, proven writable."""
    if out is not None:
        return ensure_writable_dir(out, "output folder", "--out")
    try:
        return ensure_writable_dir(results_dir, "results folder", "--out")
    except OutputError as exc:
        reason = str(exc).split(": ", 1)[-1].split(";", 1)[0]
        raise SDTError(
            f"cannot write {what} into {results_dir} ({reason}); it is read from there all the "
            f"same: add --out OTHER_FOLDER to write it elsewhere"
        ) from None
