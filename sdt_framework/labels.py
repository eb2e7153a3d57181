"""Labels from the user's data, made safe for where they go: shown, cut, or named as a file.

A label (a manifest's machine, condition, channel or run; a sweep point's
name) is text a user or a stranger's file chose: any length, any characters.
Three uses, one module:

- :func:`visible`: control and invisible format characters shown as their
  escape (``\\x1b``, ``\\u202e``), never obeyed, wherever a label is shown (the
  terminal's :class:`~sdt_framework.cli.visible.SafeConsole`, report.md and
  report.html, a figure's text);
- :func:`middle_cut`: a long label kept as its first and last characters,
  which is what tells two long names apart (the terminal and the figures);
- :func:`slug`: a file name built from labels, never a path: letters, digits
  and ``-`` only, with a short hash of the labels whenever the slug is not
  the labels themselves, so two labels never share a file.

A module of its own, importing nothing but the standard library, so the
command line's start-up does not load the data readers to shorten a message.
"""

from __future__ import annotations

import hashlib
import re
import unicodedata

__all__ = ["SLUG_PART", "middle_cut", "slug", "visible"]

#: C0 and C1 controls and DEL, except newline and tab (layout, kept).
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
#: the characters a slug keeps; anything else (``/``, ``.``, space, ``_``) becomes ``-``
_UNSAFE = re.compile(r"[^A-Za-z0-9-]+")
#: the lower-case slug characters a label may hold and still be its own slug
_PLAIN = re.compile(r"[a-z0-9]+(?:-[a-z0-9]+)*")
#: longest part of a slug, characters: file names stay well under NAME_MAX (255 bytes)
SLUG_PART = 40


def _escape(char: str) -> str:
    code = ord(char)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def visible(text: str) -> str:
    """``text`` with every control and invisible format character shown as its escape.

    >>> visible("M\\x1b]0;t\\x07 \\u202eok")
    'M\\\\x1b]0;t\\\\x07 \\\\u202eok'
    """
    text = _CONTROL.sub(lambda match: _escape(match.group()), text)
    if text.isascii():
        return text
    return "".join(_escape(char) if unicodedata.category(char) == "Cf" else char for char in text)


def middle_cut(text: str, half: int, *, count: bool = False) -> str:
    """``text`` as its first and last ``half`` characters joined by ``…``; with ``count``,
    followed by how long it was. The caller decides whether ``text`` is long enough to cut.

    >>> middle_cut("abcdefghij", 2)
    'ab…ij'
    >>> middle_cut("abcdefghij", 2, count=True)
    'ab…ij (10 characters)'
    """
    cut = f"{text[:half]}…{text[-half:]}"
    return f"{cut} ({len(text):,} characters)" if count else cut


def slug(*parts: object) -> str:
    """A file-name stem for ``parts`` (``"velocity"``, a machine, ...) joined by ``_``.

    Each part keeps its letters, digits and ``-`` (anything else becomes one
    ``-``; at most :data:`SLUG_PART` characters). When a part is not already
    lower-case letters and digits joined by single ``-`` (or is cut), a hash of all the
    parts follows (``-`` and 8 hex digits): two labels that clean to the same
    text (``a/b`` and ``a b``, or ``Pump`` and ``pump`` on a case-insensitive
    disk) still name two files. The result never holds ``/``, ``\\``, ``.`` or a
    control character, so joined to a folder it stays in that folder.

    >>> slug("velocity", "motor-2")
    'velocity_motor-2'
    >>> slug("velocity", "x/../../PWNED")
    'velocity_x-PWNED-455dc687'
    """
    texts = [str(part) for part in parts]
    cleaned = [_UNSAFE.sub("-", text).strip("-")[:SLUG_PART] for text in texts]
    stem = "_".join(cleaned)
    if all(_PLAIN.fullmatch(text) and len(text) <= SLUG_PART for text in texts):
        return stem
    digest = hashlib.sha256("\x00".join(texts).encode("utf-8", "surrogatepass")).hexdigest()
    return f"{stem}-{digest[:8]}"
