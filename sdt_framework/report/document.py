"""The report as a list of blocks, rendered once as Markdown and once as HTML.

Building the content once as data (headings, paragraphs, tables, figures,
code) keeps the two formats in step without a Markdown-to-HTML converter.

Inline text is a small subset of CommonMark written by sdt: ``**bold**``,
```code``` spans and backslash escapes. Text from the data (a machine,
condition, channel, sensor or run name, a path, an error message quoting a
file) enters it only through :func:`literal` (or :func:`code`), which
backslash-escapes what would mark it up, so ``**md**`` or
``[x](javascript:alert(1))`` in a condition shows as written in report.md and
report.html alike. The renderers add what holds for all text: control
characters shown as escapes, ``<`` never opening a tag.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "Block",
    "Code",
    "Figure",
    "Heading",
    "Items",
    "Paragraph",
    "Table",
    "code",
    "literal",
]

#: ASCII punctuation that marks text up anywhere in a line: escapes, code spans,
#: emphasis (and GFM strikethrough), links and images, entity references, heading marks
_MARKUP = re.compile(r"([\\`*_\[\]!&~#])")
#: at the start of a line: a list item ("- ", "+ "), a thematic break ("---"), a block quote
_BLOCK_MARK = re.compile(r"^(?:\+(?=[ \t]|$)|-(?=[ \t]|[- \t]*$)|>)")
#: at the start of a line: an ordered list item ("1. " or "1) ")
_ORDERED = re.compile(r"^(\d{1,9})([.)])(?=[ \t]|$)")
_NEWLINE = re.compile(r"\r\n|\r|\n")


def literal(text: object) -> str:
    """``text`` from the data as inline text that shows it as it is and marks nothing up.

    Markdown punctuation is backslash-escaped (CommonMark shows ``\\*`` as
    ``*``; the HTML renderer reads the same escapes), a list or quote mark at
    its start is escaped too (it may start a paragraph or an item), and a line
    break is shown as ``\\n``, so a label never starts a new block.

    >>> print(literal("**md** [x](javascript:alert(1))"))
    \\*\\*md\\*\\* \\[x\\](javascript:alert(1))
    """
    text = _MARKUP.sub(r"\\\1", str(text))
    text = _ORDERED.sub(r"\1\\\2", _BLOCK_MARK.sub(lambda mark: "\\" + mark.group(), text))
    return _NEWLINE.sub(r"\\n", text)


def code(text: object) -> str:
    """``text`` from the data as a code span (a name, a command), or as :func:`literal`
    text where a code span cannot hold it (a backtick, a ``<``, a line break, blank)."""
    text = str(text)
    if not text.strip() or any(char in text for char in "`<\r\n"):
        return literal(text)
    return f"`{text}`"


@dataclass(frozen=True)
class Heading:
    """A section title; ``level`` 1 is the report title."""

    text: str
    level: int = 2


@dataclass(frozen=True)
class Paragraph:
    """One paragraph of inline text."""

    text: str


@dataclass(frozen=True)
class Items:
    """A bulleted list of inline-text items."""

    items: tuple[str, ...]


@dataclass(frozen=True)
class Code:
    """A preformatted block (a config file, a command), shown verbatim."""

    text: str
    lang: str = ""


@dataclass(frozen=True)
class Table:
    """A table of inline-text cells; a row whose first cell is the only non-empty one
    and starts with ``**`` is a block heading spanning the table (Table 4 layout)."""

    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    note: str = ""


@dataclass(frozen=True)
class Figure:
    """A PNG figure: ``path`` absolute on disk, shown with its caption."""

    path: Path
    caption: str
    alt: str = ""
    extra: tuple[str, ...] = field(default_factory=tuple)


Block = Heading | Paragraph | Items | Code | Table | Figure
