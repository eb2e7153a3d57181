"""Text a user or a stranger's file chose reaches report.md and report.html inert.

A manifest path holding ESC/BEL (``ESC ] 0 ; title BEL`` sets a terminal's
title; ``ESC [ 2 J`` clears it) reached both files raw, and a ``<script>`` tag
reached report.md raw (a Markdown viewer renders HTML). The terminal already
showed such text escaped; the files now do the same: controls as ``\\x1b``,
``<script>`` as ``&lt;script>`` in Markdown and ``&lt;script&gt;`` in HTML.
Since round 4 (issue 39) the Markdown also escapes the data's Markdown
punctuation, so its brackets read ``\\[`` and ``\\]`` there (a viewer shows them as
written; test_report_hostile_labels.py renders it).
"""

from __future__ import annotations

import json

import pandas as pd

HOSTILE = "runs/\x1b]0;pwned\x07evil\x1b[2J<script>alert(1)</script>.csv"
HOSTILE_SHOWN = "runs/\\x1b]0;pwned\\x07evil\\x1b[2J"


def test_control_bytes_and_tags_are_escaped_in_both_files(sdt_in_process, monkeypatch, tmp_path):
    root = tmp_path / "res"
    root.mkdir()
    runs = [
        {"dataset": "d", "feature_set": "paper8", "machine": "M", "scenario": "forward",
         "sensor": s, "classifier": "lr", "repeat": r,
         "macro_f1": 0.5 + 0.01 * r, "status": "ok", "error": None}
        for s in ("wilcoxon-786b10", "adxl345") for r in range(2)
    ]  # fmt: skip
    pd.DataFrame(runs).to_parquet(root / "results.parquet")
    skipped = {"dataset_skipped": [{"path": HOSTILE, "reason": "no such file <b>bold</b>"}]}
    (root / "summary.json").write_text(json.dumps(skipped), encoding="utf-8")
    pd.DataFrame([{"what": HOSTILE, "why": "unreadable"}]).to_csv(root / "skipped.csv", index=False)
    # sdt's entry point in this process, the figures drawn here (as on fewer than 4 cores)
    monkeypatch.setattr("sdt_framework.report.figures.PARALLEL_FROM_CORES", 10**6)
    run = sdt_in_process("report", str(root))
    assert run.returncode == 0, run.stderr
    md = (root / "report.md").read_text(encoding="utf-8")
    page = (root / "report.html").read_text(encoding="utf-8")
    for text, shown in ((md, "runs/\\x1b\\]0;pwned\\x07evil\\x1b\\[2J"), (page, HOSTILE_SHOWN)):
        assert "\x1b" not in text and "\x07" not in text
        assert text.count(shown) == 2  # both places, escaped (brackets as Markdown literals)
        assert "<script>" not in text and "<b>bold</b>" not in text
    assert "&lt;script>alert(1)&lt;/script>" in md
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in page
    assert "\x1b" not in run.stdout + run.stderr
