"""``literal``: text from the data shows as written in report.md and report.html, marked up never.

The check is independent of the renderer's own reading: report.md is rendered
by markdown-it-py (CommonMark with GFM tables and strikethrough, as a Markdown
viewer renders it), report.html is parsed as HTML, and in both the text a
reader sees must be exactly the data (controls as their escapes) with no tag
the data asked for.
"""

from __future__ import annotations

import html
import re
import string
from html.parser import HTMLParser

import pytest
from markdown_it import MarkdownIt

from sdt_framework.labels import visible
from sdt_framework.report.document import Heading, Items, Paragraph, Table, code, literal
from sdt_framework.report.render import render_html, render_markdown

HOSTILE = [
    "**md**", "__md__", "*em*", "_em_", "~~del~~", "`code`", "``x``", "[x](javascript:alert(1))",
    "![i](x.png)", "[ref]: http://example.com", "<b>bold</b>", "<script>alert(1)</script>",
    "<!-- c -->", "<http://example.com>", "&amp; &lt;b&gt; &#42;", "a\\*b\\", "\\", "# heading",
    "a # b #", "- item", "+ item", "* item", "1. item", "2) item", "> quote", "---", "***",
    "a|b|c", "x\ny\n# z", "\x1b]0;PWN\x07", "M\x1b]0;PWN\x07<b>bold</b>", "\u202eevil",
    "3.92 EUR", "adxl355[range=8g]", "adxl345~rate=1600", "a_b_c", "Motor-2",
]  # fmt: skip
HOSTILE += list(string.punctuation) + [c * 3 for c in string.punctuation]
MD = MarkdownIt("commonmark").enable(["table", "strikethrough"])


class _Text(HTMLParser):
    """Tag names and the text a reader sees."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag: str, attrs: object) -> None:
        self.tags.append(tag)

    def handle_data(self, data: str) -> None:
        self.text.append(data)


def _read(page: str) -> _Text:
    reader = _Text()
    reader.feed(page)
    return reader


def _shown(data: str) -> str:
    """What the reader must see: the data, controls escaped, a line break as ``\\n``."""
    return visible(data).replace("\n", "\\n")


@pytest.mark.parametrize("data", HOSTILE)
@pytest.mark.parametrize("context", ["paragraph", "item", "heading", "cell", "bold"])
def test_data_shows_as_written_in_both_formats(data, context, tmp_path):
    text = literal(data)
    block, tags = {
        "paragraph": (Paragraph(f"A {text}"), {"p"}),
        "item": (Items((text,)), {"ul", "li"}),
        "heading": (Heading(text, 3), {"h3"}),
        "cell": (Table(("name",), ((text,),)), {"table", "thead", "tbody", "tr", "th", "td"}),
        "bold": (Paragraph(f"**{text}**"), {"p", "strong"}),
    }[context]
    expected = _shown(data)
    if context == "paragraph":
        expected = f"A {expected}"
    page = render_html([block], "t")
    body = page.split("<body>\n", 1)[1].rsplit("\n</body>", 1)[0]
    for shown_page in (MD.render(render_markdown([block], tmp_path)), body):
        reader = _read(shown_page)
        assert set(reader.tags) <= tags | {"div"}, (shown_page, set(reader.tags) - tags)
        shown = "".join(reader.text).replace("\n", " ").strip()
        if context == "cell":
            shown = shown.removeprefix("name").strip()
        assert shown == expected.strip(), (repr(data), context, shown_page)


@pytest.mark.parametrize("data", ["wilcoxon-786b10", "a`b", "a<b", "x\ny", "  "])
def test_code_spans_hold_a_name_or_fall_back_to_literal_text(data, tmp_path):
    page = MD.render(render_markdown([Paragraph(code(data))], tmp_path))
    reader = _read(page)
    assert "".join(reader.text).strip() == _shown(data).strip()
    assert ("code" in reader.tags) == (data == "wilcoxon-786b10")


def test_a_page_title_and_alt_text_show_the_data_unmarked():
    page = render_html([Heading(literal("**x** <b>"), 1)], f"report: {literal('**x** <b>')}")
    assert "<title>report: **x** &lt;b&gt;</title>" in page
    assert re.search(r"<h1>\*\*x\*\* &lt;b&gt;</h1>", page)
    assert html.unescape("&lt;b&gt;") == "<b>"
