"""A verdict label is printed beside the intervals it rests on, so the two never contradict.

Constructed folder: one machine and scenario, two classes of two test recordings
each. The reference classifies every window right; the candidate gets recording
``a2`` partly wrong (4 or 5 of its 10 windows called ``b``) in every repetition.
The repetition interval is tight around Δ ≈ -0.11, wholly below -0.02, but a
recording resample that draws ``a1`` twice leaves the candidate error-free (Δ = 0),
which happens in a quarter of the draws: the recording interval's upper end is
exactly 0, it crosses the margin, and the label is "inconclusive". Before the fix
the report's group table printed "inconclusive Δ -0.114 [-0.138, -0.090]", an
interval that by itself says "worse".
"""

from __future__ import annotations

import re

import pandas as pd
from sklearn.metrics import f1_score

RECORDINGS = {"a1": "a", "a2": "a", "b1": "b", "b2": "b"}
WRONG = [4, 5, 4, 5]  # windows of a2 the candidate calls b, per repetition
MARGIN = 0.02


def _folder(root):
    runs, counts = [], []
    for sensor in ("wilcoxon-786b10", "cand"):
        for classifier in ("lr", "rf"):
            for repeat, wrong in enumerate(WRONG):
                key = {
                    "dataset": "d", "feature_set": "paper8", "machine": "M", "scenario": "forward",
                    "sensor": sensor, "classifier": classifier, "repeat": repeat,
                }  # fmt: skip
                y_true, y_pred = [], []
                for rec, cls in RECORDINGS.items():
                    bad = wrong if (sensor == "cand" and rec == "a2") else 0
                    for predicted, n in ((cls, 10 - bad), ("b", bad)):
                        if n:
                            counts.append({**key, "recording_id": rec, "true": cls,
                                           "predicted": predicted, "count": n})  # fmt: skip
                            y_true += [cls] * n
                            y_pred += [predicted] * n
                f1 = f1_score(y_true, y_pred, average="macro")
                runs.append({**key, "macro_f1": f1, "n_test": 40, "status": "ok", "error": None})
    root.mkdir()
    pd.DataFrame(runs).to_parquet(root / "results.parquet")
    pd.DataFrame(counts).to_parquet(root / "per_recording.parquet")
    return pd.DataFrame(runs)


def _label(low: float, high: float) -> str:
    """The rule of docs/report.md, written out here for one interval."""
    if high < -MARGIN:
        return "worse"
    if low > MARGIN:
        return "better"
    if low > -MARGIN and high < MARGIN:
        return "equivalent"
    return "inconclusive"


NUM = r"([+-]\d\.\d{3})"
PRINTED = re.compile(
    rf"\*\*(equivalent|worse|better|inconclusive)\*\* Δ {NUM} \[{NUM}, {NUM}\]"
    rf"(?:; recording CI \[{NUM}, {NUM}\])?"
)


def test_group_table_label_agrees_with_the_printed_intervals(sdt_in_process, tmp_path):
    runs = _folder(tmp_path / "res")
    result = sdt_in_process("report", str(tmp_path / "res"), "--format", "md")  # no worker
    assert result.returncode == 0, result.stderr
    text = (tmp_path / "res" / "report.md").read_text(encoding="utf-8")
    text = re.sub(r"\\([\[\]])", r"\1", text)  # as a Markdown viewer shows "\[" (literal text)
    table_rows = [line for line in text.splitlines() if line.startswith("| M | forward |")]
    assert len(table_rows) == 1, text
    found = PRINTED.findall(table_rows[0])
    assert len(found) == 1, table_rows[0]
    label, delta, low, high, rec_low, rec_high = found[0]
    wide = runs.pivot_table(index=["classifier", "repeat"], columns="sensor", values="macro_f1")
    expected_delta = (wide["cand"] - wide["wilcoxon-786b10"]).mean()
    assert float(delta) == round(expected_delta, 3)
    assert _label(float(low), float(high)) == "worse"  # the repetition interval alone
    assert rec_high, "the recording interval the label rests on is not printed"
    assert float(rec_high) == 0.0  # a quarter of the draws hold a1 twice: Δ = 0 exactly
    assert _label(float(rec_low), float(rec_high)) == "inconclusive"
    both = {_label(float(low), float(high)), _label(float(rec_low), float(rec_high))}
    assert label == (both.pop() if len(both) == 1 else "inconclusive")
    # every label in the verdict's sentences sits beside both of its intervals too
    verdict = text.split("## Verdict")[1].split("\n## ")[0]
    shown = re.findall(rf"Δ {NUM} \[{NUM}, {NUM}\](; recording CI)?", verdict)
    assert len(shown) >= 4  # group and overall sentences, each cell of the group
    assert all(rec for *_, rec in shown), verdict


def test_calibrate_pump_findings_print_the_figure_and_rule_the_label_rests_on():
    """``benchmarks/calibrate_pump.py``: "held ... F1 >= 0.9 ...: 0.60" read as an F1 of 0.60.

    Each line now names what its number measures and the threshold it is judged
    by; the label is re-derived here from the printed threshold alone.
    """
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "benchmarks" / "calibrate_pump.py"
    spec = importlib.util.spec_from_file_location("calibrate_pump", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    line = re.compile(
        r"^  (held    |not held)  (.+): (.+) = (-?\d+\.\d\d) \(held when (>=|<=|>|<) ([\d.]+)"
    )
    compare = {">": float.__gt__, ">=": float.__ge__, "<": float.__lt__, "<=": float.__le__}
    for text in module.CHECKS:
        for value in (0.0, 0.41, 0.6, 0.8, 3.33, 5.0):
            printed = module.finding_line(text, value)
            match = line.match(printed)
            assert match, printed
            label, finding, _measure, shown, op, threshold = match.groups()
            assert finding == text and float(shown) == value
            assert (label.strip() == "held") == compare[op](float(shown), float(threshold)), printed
    discharge = module.finding_line(
        "cavitation discharge F1 >= 0.9 for most classifiers in every scenario", 0.6
    )
    assert "share of classifiers with F1 >= 0.9 (worst scenario) = 0.60" in discharge
