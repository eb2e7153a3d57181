"""Render report blocks as Markdown (figures linked) or self-contained HTML (figures inlined).

The HTML page has its style inline and every figure as a ``data:image/png;base64``
URI: one file that opens anywhere, offline, with no external CSS, JS or fonts.

Inline text is the subset :mod:`.document` defines (``**bold**``, ```code```,
backslash escapes; data enters through :func:`.document.literal`). Both
renderers show every control character as its escape
(:func:`sdt_framework.labels.visible`) and never let a ``<`` open a tag.
"""

from __future__ import annotations

import base64
import html
import os
import re
from collections.abc import Sequence
from pathlib import Path
from urllib.parse import quote

from ..labels import visible
from .document import Block, Code, Figure, Heading, Items, Paragraph, Table

__all__ = ["render_html", "render_markdown"]

#: the inline subset, left to right: a backslash escape of ASCII punctuation, a code
#: span, a bold span (whose text may hold escapes, ``\*`` never closing it)
_INLINE = re.compile(r"\\([!-/:-@\[-`{-~])|`([^`]+)`|\*\*((?:\\.|[^\\])+?)\*\*")
#: a "<" that would open an HTML tag, comment or declaration in a Markdown viewer
_TAG_START = re.compile(r"<(?=[A-Za-z/!?])")
_BACKTICKS = re.compile(r"`+")
_CSS = """
body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;margin:2em auto;
max-width:1200px;padding:0 1em;color:#222;line-height:1.45}
h1{border-bottom:2px solid #ccc}h2{border-bottom:1px solid #ddd;margin-top:2em}
table{border-collapse:collapse;margin:1em 0;font-size:.85em}
th,td{border:1px solid #ccc;padding:.25em .5em;text-align:right;white-space:nowrap}
th:first-child,td:first-child{text-align:left}th{background:#f0f0f0}
tr.block td{background:#fafafa;text-align:left}
figure{margin:1.5em 0}figure img{max-width:100%;height:auto;border:1px solid #eee}
figcaption,.note{font-size:.9em;color:#555}
pre{background:#f6f6f6;padding:.8em;overflow-x:auto;font-size:.85em}
code{background:#f3f3f3;padding:0 .2em}.scroll{overflow-x:auto}
"""


def _md(text: str) -> str:
    """Markdown text with controls escaped and tag openers neutralised (``<script>`` shown)."""
    return _TAG_START.sub("&lt;", visible(text))


def _inline(text: str) -> str:
    """HTML of inline text whose controls are already escaped."""
    out, end = [], 0
    for match in _INLINE.finditer(text):
        out.append(html.escape(text[end : match.start()], quote=False))
        escaped, span, bold = match.groups()
        if escaped is not None:
            out.append(html.escape(escaped, quote=False))
        elif span is not None:
            out.append(f"<code>{html.escape(span, quote=False)}</code>")
        else:
            out.append(f"<strong>{_inline(bold)}</strong>")
        end = match.end()
    return "".join(out) + html.escape(text[end:], quote=False)


def _inline_html(text: str) -> str:
    return _inline(visible(text))


def _unmarked(text: str) -> str:
    """Inline text with its markup removed (an image's alt text, the page title)."""

    def plain(match: re.Match[str]) -> str:
        escaped, span, bold = match.groups()
        return escaped if escaped is not None else span if span is not None else _unmarked(bold)

    return _INLINE.sub(plain, text)


def _inline_text(text: str) -> str:
    return _unmarked(visible(text))


def _fence(text: str) -> str:
    """A code fence longer than any run of backticks in ``text`` (CommonMark's rule)."""
    longest = max((len(run) for run in _BACKTICKS.findall(text)), default=0)
    return "`" * max(3, longest + 1)


def _is_block_row(row: Sequence[str]) -> bool:
    return row[0].startswith("**") and not any(row[1:])


def _md_cell(text: str) -> str:
    return _md(text).replace("|", "\\|").replace("\n", " ")


def render_markdown(blocks: Sequence[Block], base: str | os.PathLike[str]) -> str:
    """Markdown text; figures are linked relative to ``base`` (the report's folder)."""
    out: list[str] = []
    for block in blocks:
        if isinstance(block, Heading):
            out.append(f"{'#' * block.level} {_md(block.text)}")
        elif isinstance(block, Paragraph):
            out.append(_md(block.text))
        elif isinstance(block, Items):
            out.append("\n".join(f"- {_md(item)}" for item in block.items))
        elif isinstance(block, Code):
            text = visible(block.text.rstrip())
            fence = _fence(text)
            out.append(f"{fence}{block.lang}\n{text}\n{fence}")
        elif isinstance(block, Table):
            lines = ["| " + " | ".join(_md_cell(c) for c in block.header) + " |"]
            lines.append("|" + "---|" * len(block.header))
            lines += ["| " + " | ".join(_md_cell(c) for c in row) + " |" for row in block.rows]
            out.append("\n".join(lines) + (f"\n\n{_md(block.note)}" if block.note else ""))
        elif isinstance(block, Figure):
            rel = quote(Path(os.path.relpath(block.path, base)).as_posix())
            out.append(f"![{_md(block.alt or block.caption)}]({rel})\n\n*{_md(block.caption)}*")
            out += [_md(extra) for extra in block.extra]
    return "\n\n".join(out) + "\n"


def _html_table(table: Table) -> str:
    head = "".join(f"<th>{_inline_html(c)}</th>" for c in table.header)
    rows = []
    for row in table.rows:
        if _is_block_row(row):
            span = len(table.header)
            rows.append(f'<tr class="block"><td colspan="{span}">{_inline_html(row[0])}</td></tr>')
        else:
            rows.append("<tr>" + "".join(f"<td>{_inline_html(c)}</td>" for c in row) + "</tr>")
    note = f'<p class="note">{_inline_html(table.note)}</p>' if table.note else ""
    table_html = f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(rows)}</tbody></table>"
    return f'<div class="scroll">{table_html}</div>{note}'


def render_html(blocks: Sequence[Block], title: str) -> str:
    """One self-contained HTML page: inline CSS, figures as base64 PNG data URIs."""
    body: list[str] = []
    for block in blocks:
        if isinstance(block, Heading):
            level = min(max(block.level, 1), 6)
            body.append(f"<h{level}>{_inline_html(block.text)}</h{level}>")
        elif isinstance(block, Paragraph):
            body.append(f"<p>{_inline_html(block.text)}</p>")
        elif isinstance(block, Items):
            items = "".join(f"<li>{_inline_html(i)}</li>" for i in block.items)
            body.append(f"<ul>{items}</ul>")
        elif isinstance(block, Code):
            body.append(f"<pre><code>{html.escape(visible(block.text.rstrip()))}</code></pre>")
        elif isinstance(block, Table):
            body.append(_html_table(block))
        elif isinstance(block, Figure):
            data = base64.b64encode(Path(block.path).read_bytes()).decode("ascii")
            alt = html.escape(_inline_text(block.alt or block.caption))
            extra = "".join(f"<p>{_inline_html(e)}</p>" for e in block.extra)
            body.append(
                f'<figure><img alt="{alt}" src="data:image/png;base64,{data}">'
                f"<figcaption>{_inline_html(block.caption)}</figcaption></figure>{extra}"
            )
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{html.escape(_inline_text(title))}</title><style>{_CSS}</style></head>\n<body>\n"
        + "\n".join(body)
        + "\n</body></html>\n"
    )
