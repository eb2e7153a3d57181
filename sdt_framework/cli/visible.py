"""User strings made safe for a terminal: control characters shown, never obeyed.

A sensor file's ``description``, a manifest path or a message quoting a file
is text a user (or a stranger's file) chose. Printed raw, an escape sequence in
it would set the terminal's title, clear the screen or hide what follows
(``ESC ] 0 ; … BEL``, ``ESC [ 2 J``); a bidirectional override would reorder
the line the user reads. Every such character is printed as its escape
(``\\x1b``, ``\\u202e``) instead. Newlines and tabs are layout and stay.
"""

from __future__ import annotations

import re
import unicodedata

from rich.console import Console
from rich.text import Text

__all__ = ["SafeConsole", "visible"]

#: C0 and C1 controls and DEL, except newline and tab.
_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")


def _escape(char: str) -> str:
    code = ord(char)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def visible(text: str) -> str:
    """``text`` with every control and invisible format character shown as its escape."""
    text = _CONTROL.sub(lambda match: _escape(match.group()), text)
    if text.isascii():
        return text
    return "".join(_escape(char) if unicodedata.category(char) == "Cf" else char for char in text)


class SafeConsole(Console):
    """A rich console that prints every string it is given through :func:`visible`.

    Strings reach the terminal through :meth:`render_str` (``print``, table cells
    and titles, progress descriptions); :class:`~rich.text.Text` built by sdt
    itself is escaped where it is built (``cli.common.print_error``).
    """

    def render_str(self, text: str, **kwargs: object) -> Text:  # type: ignore[override]
        """Escape control characters, then render as rich does."""
        return super().render_str(visible(text), **kwargs)  # type: ignore[arg-type]
