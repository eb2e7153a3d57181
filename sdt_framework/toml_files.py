"""Reading a user's TOML file: bytes, UTF-8, TOML, one line naming the file on any fault.

Configs, sweep files, sensor profiles and part files are all hand-edited TOML.
Each fault a user can make in one — a missing file, a folder, a file too large
to be a config (``/dev/zero``), text saved as Latin-1 or UTF-16, a NUL byte,
broken TOML, values nested so deep the parser or the validator would exhaust
Python's recursion limit — becomes one :class:`~sdt_framework.errors.SpecFileError`
naming the file (and the line, or the key, where known) and what to do, here
once instead of in every reader. A UTF-8 byte-order mark (Windows editors add
one) is accepted.
"""

from __future__ import annotations

import codecs
import os
import tomllib
from pathlib import Path
from typing import Any

from .errors import SpecFileError
from .inputs import require_regular_file

__all__ = ["MAX_BYTES", "MAX_DEPTH", "parse_toml", "read_toml"]

#: A config or profile is a few kB; above this the file is not one (or is a device).
MAX_BYTES = 16 * 2**20
#: Arrays/tables nested deeper than this are refused (real files nest 4 or 5 levels).
MAX_DEPTH = 32

_WIDE_BOMS = {
    codecs.BOM_UTF32_LE: "UTF-32",
    codecs.BOM_UTF32_BE: "UTF-32",
    codecs.BOM_UTF16_LE: "UTF-16",
    codecs.BOM_UTF16_BE: "UTF-16",
}


def read_toml(
    path: str | os.PathLike[str],
    *,
    what: str = "file",
    missing: str = "file not found; check the path",
) -> dict[str, Any]:
    """The parsed TOML file at ``path``; ``missing`` is the advice when it does not exist.

    ``what`` names the file's role (``config file``, ``sensor file``) when ``path``
    is a device or a pipe, which is refused unread.
    """
    path = Path(path)
    require_regular_file(path, what)
    try:
        with path.open("rb") as handle:
            raw = handle.read(MAX_BYTES + 1)
    except FileNotFoundError:
        raise SpecFileError(path, "", missing) from None
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise SpecFileError(path, "", f"cannot read: {reason}; give a readable TOML file") from None
    if len(raw) > MAX_BYTES:
        raise SpecFileError(
            path,
            "",
            f"larger than {MAX_BYTES // 2**20} MB, too large for a TOML config or profile; "
            f"check that this is the right file",
        )
    return parse_toml(raw, path)


def parse_toml(content: bytes | str, where: str | os.PathLike[str]) -> dict[str, Any]:
    """Parse TOML ``content`` (bytes are decoded as UTF-8); ``where`` names it in errors."""
    text = _decode(content, where) if isinstance(content, bytes) else content
    if "\x00" in text:
        line = text.count("\n", 0, text.index("\x00")) + 1
        raise SpecFileError(
            where,
            "",
            f"holds a NUL byte (line {line}): a binary or UTF-16 file? "
            f"save it as a UTF-8 TOML file",
        )
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SpecFileError(where, "", f"not valid TOML: {exc}") from None
    except RecursionError:
        raise SpecFileError(
            where, "", f"nests arrays or tables too deep to read (limit {MAX_DEPTH} levels)"
        ) from None
    key = _too_deep(data)
    if key is not None:
        raise SpecFileError(
            where,
            key,
            f"nests arrays or tables more than {MAX_DEPTH} levels deep; "
            f"no setting needs more than a few",
        )
    return data


def _decode(raw: bytes, where: str | os.PathLike[str]) -> str:
    for bom, name in _WIDE_BOMS.items():
        if raw.startswith(bom):
            raise SpecFileError(where, "", f"is {name} text; save it as a UTF-8 TOML file")
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        column = exc.start - (raw.rfind(b"\n", 0, exc.start) + 1) + 1
        raise SpecFileError(
            where,
            "",
            f"not UTF-8 text (byte {exc.start} = 0x{raw[exc.start]:02x}, line {line}, column "
            f"{column}); save it as a UTF-8 TOML file",
        ) from None


def _too_deep(data: dict[str, Any]) -> str | None:
    """The top-level key under which values nest deeper than MAX_DEPTH, else None.

    Walked with an explicit stack: a recursive walk would fail exactly where it must not.
    """
    stack: list[tuple[object, int, str]] = [(value, 1, key) for key, value in data.items()]
    while stack:
        value, depth, key = stack.pop()
        if depth > MAX_DEPTH:
            return key
        if isinstance(value, dict):
            stack.extend((child, depth + 1, key) for child in value.values())
        elif isinstance(value, list):
            stack.extend((child, depth + 1, key) for child in value)
    return None
