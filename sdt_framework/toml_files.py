"""Reading a user's file: bytes, UTF-8, TOML, a pydantic model; any fault is one line.

Configs, sweep files, sensor profiles, part files, twin pair files and
allocation tables are hand-edited text, read here in four steps:
:func:`read_bytes` (a regular file of sane size), :func:`decode_text`
(UTF-8; UTF-16/32, other bytes and NUL refused), :func:`parse_toml` and
:func:`validate_file` (a pydantic model; its error becomes the file, the
field, the reason and, per kind of file, where to look the fields up).
:func:`read_toml` is the first three; an allocation CSV takes the first two.
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
from typing import Any, TypeVar

from pydantic import BaseModel, ValidationError

from .errors import SpecFileError, field_errors
from .inputs import require_regular_file

__all__ = [
    "MAX_BYTES",
    "MAX_DEPTH",
    "decode_text",
    "parse_toml",
    "read_bytes",
    "read_toml",
    "validate_file",
]

M = TypeVar("M", bound=BaseModel)

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


def read_bytes(
    path: str | os.PathLike[str],
    *,
    what: str = "file",
    missing: str = "file not found; check the path",
    unreadable: str = "cannot read: {reason}; give a readable TOML file",
) -> bytes:
    """The bytes of the user's file at ``path``, refused above :data:`MAX_BYTES`.

    ``what`` names the file's role (``config file``, ``sensor file``) when
    ``path`` is a device or a pipe, which is refused unread; ``missing`` is the
    advice when it does not exist, ``unreadable`` (with ``{reason}``) when the
    system refuses to read it.
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
        raise SpecFileError(path, "", unreadable.format(reason=reason)) from None
    if len(raw) > MAX_BYTES:
        raise SpecFileError(
            path,
            "",
            f"larger than {MAX_BYTES // 2**20} MB, too large for a TOML config or profile; "
            f"check that this is the right file",
        )
    return raw


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
    return parse_toml(read_bytes(path, what=what, missing=missing), path)


def validate_file(
    model: type[M],
    data: Any,
    where: str | os.PathLike[str],
    *,
    prefix: str = "",
    unknown: str = "unknown field",
    show_input: bool = False,
) -> M:
    """``data`` read from the file ``where`` validated as ``model``; its first fault is one line.

    The :class:`SpecFileError` names the file, the field (``prefix`` before it,
    e.g. ``sensor[0].`` for a profile in an array of tables) and the reason,
    as :func:`~sdt_framework.errors.field_errors` words it (``unknown`` for a
    key the model lacks: say there where the keys are listed; ``show_input``
    adds the value given).
    """
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        field, reason = field_errors(exc, unknown=unknown, show_input=show_input)[0]
        raise SpecFileError(where, (prefix + field).rstrip("."), reason) from None


def parse_toml(content: bytes | str, where: str | os.PathLike[str]) -> dict[str, Any]:
    """Parse TOML ``content`` (bytes are decoded as UTF-8); ``where`` names it in errors."""
    text = decode_text(content, where) if isinstance(content, bytes) else content
    _no_nul(text, where, "TOML file")
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


def _no_nul(text: str, where: str | os.PathLike[str], kind: str) -> None:
    if "\x00" in text:
        line = text.count("\n", 0, text.index("\x00")) + 1
        raise SpecFileError(
            where,
            "",
            f"holds a NUL byte (line {line}): a binary or UTF-16 file? save it as a UTF-8 {kind}",
        )


def decode_text(raw: bytes, where: str | os.PathLike[str], kind: str = "TOML file") -> str:
    """``raw`` as UTF-8 text (a UTF-8 byte-order mark dropped); any other encoding is refused.

    UTF-16/32 (by their byte-order mark), a byte that is not UTF-8 (named with
    its line and column) and a NUL byte are each one :class:`SpecFileError`
    saying to save the file as a UTF-8 ``kind``.
    """
    for bom, name in _WIDE_BOMS.items():
        if raw.startswith(bom):
            raise SpecFileError(where, "", f"is {name} text; save it as a UTF-8 {kind}")
    try:
        text = raw.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        column = exc.start - (raw.rfind(b"\n", 0, exc.start) + 1) + 1
        raise SpecFileError(
            where,
            "",
            f"not UTF-8 text (byte {exc.start} = 0x{raw[exc.start]:02x}, line {line}, column "
            f"{column}); save it as a UTF-8 {kind}",
        ) from None
    _no_nul(text, where, kind)
    return text


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
