"""The report as a list of blocks, rendered once as Markdown and once as HTML.

Building the content once as data (headings, paragraphs, tables, figures,
code) keeps the two formats in step without a Markdown-to-HTML converter.
Inline text may carry ``**bold**`` and ```code``` spans; everything else is
literal text (escaped in HTML).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

__all__ = ["Block", "Code", "Figure", "Heading", "Items", "Paragraph", "Table"]


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
