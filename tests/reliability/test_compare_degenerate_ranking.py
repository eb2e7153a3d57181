"""The Friedman ranking on blocks where every sensor scores the same: one line, no warning.

On main ``sdt compare`` printed scipy's raw ``RuntimeWarning: invalid value
encountered in scalar divide`` (the tie-corrected statistic is 0/0) and a
ranking of NaN. Now the ranking line says what was degenerate.
"""

from __future__ import annotations

import subprocess
import sys

import pandas as pd


def test_all_tied_blocks_are_named_not_warned(tmp_path):
    root = tmp_path / "res"
    root.mkdir()
    runs = [
        {"dataset": "d", "feature_set": "paper8", "machine": "M", "scenario": scenario,
         "sensor": sensor, "classifier": "lr", "repeat": repeat, "macro_f1": 0.5,
         "status": "ok", "error": None}
        for scenario in ("forward", "backward")
        for sensor in ("wilcoxon-786b10", "adxl345", "adxl357")
        for repeat in range(2)
    ]  # fmt: skip
    pd.DataFrame(runs).to_parquet(root / "results.parquet")
    run = subprocess.run(
        [sys.executable, "-m", "sdt_framework", "compare", str(root), "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        check=False,
        env={"PATH": "/usr/bin:/bin", "COLUMNS": "300", "PYTHONWARNINGS": "default"},
    )
    assert run.returncode == 0, run.stderr
    assert "Warning" not in run.stderr and "nan" not in run.stdout.lower().split("ranking")[-1]
    ranking = [line for line in run.stdout.splitlines() if line.startswith("ranking:")]
    assert ranking == [
        "ranking: Friedman/Nemenyi not computed: every one of the 2 blocks gives all 3 sensors "
        "the same Macro F1 (e.g. 0.500), so there is nothing to rank."
    ]
