"""User strings made safe for a terminal: control characters shown, never obeyed.

A sensor file's ``description``, a manifest path or a message quoting a file
is text a user (or a stranger's file) chose. Printed raw, an escape sequence in
it would set the terminal's title, clear the screen or hide what follows
(``ESC ] 0 ; … BEL``, ``ESC [ 2 J``); a bidirectional override would reorder
the line the user reads. Every such character is printed as its escape
(``\\x1b``, ``\\u202e``) instead. Newlines and tabs are layout and stay. The
escaping itself is :func:`sdt_framework.labels.visible`, shared with the report.
"""

from __future__ import annotations

from rich.console import Console
from rich.text import Text

from ..labels import visible

__all__ = ["SafeConsole", "visible"]


class SafeConsole(Console):
    """A rich console that prints every string it is given through :func:`visible`.

    Strings reach the terminal through :meth:`render_str` (``print``, table cells
    and titles, progress descriptions); :class:`~rich.text.Text` built by sdt
    itself is escaped where it is built (``cli.common.print_error``).
    """

    def render_str(self, text: str, **kwargs: object) -> Text:  # type: ignore[override]
        """Escape control characters, then render as rich does."""
        return super().render_str(visible(text), **kwargs)  # type: ignore[arg-type]
