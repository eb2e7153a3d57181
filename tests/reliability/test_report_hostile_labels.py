"""Labels that hold paths, controls, HTML and Markdown: every output stays inside --out, inert.

On main (issue 39, items 1 and 2) a manifest machine named
``x/../../../../PWNED``, graded by a zone table, made the report write
``PWNED.png`` four folders above the results folder (exit 0): the spectral
figures were named ``velocity_{machine}.png`` from the raw label. The same
figure links carried ESC, BEL and a raw ``<b>`` into report.md;
``[x](javascript:alert(1))`` in a condition stayed a live link in report.md
and ``**md**`` rendered bold in report.html; matplotlib's "Glyph 27 missing"
warnings printed the raw ESC/BEL on the terminal.

Here a real ``sdt benchmark`` (and ``sdt report --out`` elsewhere) runs on a
manifest whose machine, condition, channel and run hold all of that, and then
on the same folder with its sensor names replaced likewise. Every file written
must lie inside the folder named; report.md is rendered by a CommonMark
parser (markdown-it-py, what a viewer does) and report.html parsed, and
neither may hold a raw control character, a tag or link of the data's, or the
data's emphasis; nor may the terminal.
"""

from __future__ import annotations

import csv
import json
import re
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pandas as pd
from markdown_it import MarkdownIt
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from ..helpers import MANIFEST_HEADER

CONTROLS = "\x1b]0;PWN\x07\x1b[2J"
MARKUP = "<b>bold</b> **md** [x](javascript:alert(1)) <i>it</i> _em_ ~~del~~"
MACHINE = f"x/../../../../PWNED{CONTROLS}{MARKUP}"
CONDITION = f"../{CONTROLS}[x](javascript:alert(1)) **md** <u>u</u> |"
CHANNEL = f"ch1/../..{CONTROLS}<b>c</b>"
RUN = f"r/../{CONTROLS}`tick`"
SENSORS = {  # a results folder's sensor names, replaced in phase 2
    "wilcoxon-786b10": f"ref/../../{CONTROLS}<b>ref</b>**md**",
    "adxl345": f"s/..{CONTROLS}[x](javascript:alert(1))<script>alert(1)</script>",
}
#: the tags sdt's own report.html uses; the data adds none
OWN_TAGS = {
    "html", "head", "meta", "title", "style", "body", "h1", "h2", "h3", "h4", "h5", "h6",
    "p", "ul", "li", "pre", "code", "table", "thead", "tbody", "tr", "th", "td", "div",
    "figure", "img", "figcaption", "strong",
}  # fmt: skip
RAW_CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")


def _files(root: Path) -> set[Path]:
    return {p for p in root.rglob("*") if p.is_file() or p.is_symlink()}


def _manifest(folder: Path) -> Path:
    """The synthetic pump's Motor-2 ch1 (15 recordings) under hostile labels."""
    folder.mkdir(parents=True)
    manifest = folder / "manifest.csv"
    with manifest.open("w", encoding="utf-8", newline="") as handle:
        handle.write(MANIFEST_HEADER)
        rows = csv.writer(handle)
        for index, (rec, data) in enumerate(
            open_synthetic(machines="Motor-2", channels="ch1", duration=1.5).iter_loaded()
        ):
            np.save(folder / f"f{index}.npy", data[0])
            severity = "" if rec.severity is None else str(rec.severity)
            rows.writerow((f"f{index}.npy", 20000, MACHINE, f"{CONDITION} {rec.condition}",
                           severity, f"{RUN} {rec.run}", CHANNEL))  # fmt: skip
    return manifest


class _Tags(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.tags: set[str] = set()
        self.links: list[str] = []  # every href and src

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.add(tag)
        self.links += [value or "" for name, value in attrs if name in ("href", "src")]


def _check_html(page: str, own: set[str] = OWN_TAGS) -> None:
    """A parsed page: sdt's own tags only, no script or link, the data's markup shown."""
    assert not RAW_CONTROL.search(page), RAW_CONTROL.search(page)
    parser = _Tags()
    parser.feed(page)
    assert parser.tags <= own, parser.tags - own
    assert all(link.startswith(("figures/", "data:image/png;base64,")) for link in parser.links)
    assert not re.search(r"<strong>\s*md\s*</strong>", page)  # **md** stays two stars


def _check_report(out: Path, stdout: str, stderr: str) -> None:
    md = (out / "report.md").read_text(encoding="utf-8")
    assert not RAW_CONTROL.search(md), RAW_CONTROL.search(md)
    prose = re.sub(r"^(`{3,}).*?^\1$", "", md, flags=re.S | re.M)  # config.toml: code, inert
    assert not re.search(r"<(b|i|u|script)>", prose)  # no tag of the data's, raw
    # rendered as a CommonMark (+ tables, strikethrough) viewer renders it
    rendered = MarkdownIt("commonmark").enable(["table", "strikethrough"]).render(md)
    _check_html(rendered, OWN_TAGS | {"em"})  # sdt writes a figure's caption in italics
    assert not re.search(r"<em>\s*em\s*</em>", rendered)  # the data's _em_ stays as written
    assert "**md**" in rendered and "[x](javascript:alert(1))" in rendered and "_em_" in rendered
    for source in re.findall(r'<img src="([^"]+)"', rendered):
        assert re.fullmatch(r"figures/[A-Za-z0-9_.-]+\.png", source), source
        assert (out / source).is_file()
    _check_html((out / "report.html").read_text(encoding="utf-8"))
    terminal = stdout + stderr
    assert not RAW_CONTROL.search(terminal), terminal[:2000]
    assert "Glyph" not in terminal  # matplotlib drew no raw control character


def test_benchmark_and_report_on_hostile_labels_write_only_inside_out(sdt, tmp_path):
    deep = tmp_path / "d1" / "d2" / "d3" / "d4" / "d5"
    manifest = _manifest(deep / "data")
    config = deep / "bench.toml"
    table = "iso10816-3-group2-rigid"
    config.write_text(f"[benchmark]\nzones = {{ {json.dumps(MACHINE)} = {json.dumps(table)} }}\n")
    out = deep / "results"
    before = _files(tmp_path)

    done = sdt("benchmark", str(config), "--data", str(manifest), "--quick", "--classifiers",
               "lr", "--sensors", ",".join(SENSORS), "--jobs", "1", "--out", str(out))  # fmt: skip
    assert done.returncode == 0, done.stderr[-3000:]
    written = _files(tmp_path) - before
    cache = tmp_path / "cache"
    outside = [p for p in written if not p.is_relative_to(out) and not p.is_relative_to(cache)]
    assert not outside, outside  # on main: PWNED...png four folders up
    figures = sorted(p.name for p in (out / "figures").iterdir())
    assert all(re.fullmatch(r"[A-Za-z0-9_.-]+\.png", name) for name in figures), figures
    assert sum(name.startswith(("velocity_x-PWNED-", "levels_x-PWNED-")) for name in figures)
    assert "velocity" in (out / "report.md").read_text(encoding="utf-8")  # drawn, linked
    _check_report(out, done.stdout, done.stderr)

    # phase 2: the same folder with hostile sensor names, reported into another folder
    for name in ("results", "per_class", "confusion", "per_recording", "features"):
        path = out / f"{name}.parquet"
        frame = pd.read_parquet(path)
        frame["sensor"] = frame["sensor"].replace(SENSORS)
        frame.to_parquet(path)
    (out / "results.csv").unlink()
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    summary["reference"] = SENSORS["wilcoxon-786b10"]
    summary["saturation"] = {SENSORS["adxl345"]: summary.get("saturation", {}).get("adxl345")}
    if summary["saturation"][SENSORS["adxl345"]] is None:
        del summary["saturation"]
    (out / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
    text = (out / "config.toml").read_text(encoding="utf-8")
    for old, new in SENSORS.items():
        text = text.replace(json.dumps(old), json.dumps(new))
    (out / "config.toml").write_text(text, encoding="utf-8")
    other = deep / "report-elsewhere"
    before = _files(tmp_path)

    done = sdt("report", str(out), "--out", str(other))
    assert done.returncode == 0, done.stderr[-3000:]
    written = _files(tmp_path) - before
    assert written and all(p.is_relative_to(other) for p in written), written
    md = (other / "report.md").read_text(encoding="utf-8")
    assert "s/..\\x1b" in md  # the sensor names reached the report, escaped
    _check_report(other, done.stdout, done.stderr)
