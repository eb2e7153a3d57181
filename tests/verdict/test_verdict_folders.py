"""``verdict.pair_folders``: two results folders named by what differs, paired run by run."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.verdict import folder_labels, pair_folders

CELLS = [
    (m, s, n, c)
    for m in ("Motor-2", "Motor-4")
    for s in ("forward", "backward")
    for n in ("ref", "adxl345")
    for c in ("lr", "knn")
]


def _folder(shift: float = 0.0, feature_set: str = "paper8", dataset: str = "pump") -> pd.DataFrame:
    """A results table: 8 cells x 5 repetitions, Macro F1 drawn once (seed 0) plus ``shift``."""
    rng = np.random.default_rng(0)
    rows = [
        dict(dataset=dataset, feature_set=feature_set, machine=m, scenario=s, sensor=n,
             classifier=c, repeat=r, macro_f1=rng.uniform(0.3, 0.9) + shift, status="ok")
        for m, s, n, c in CELLS
        for r in range(5)
    ]  # fmt: skip
    return pd.DataFrame(rows)


def test_folders_are_named_by_what_differs():
    a, b = Path("results/a"), Path("other/b")
    assert folder_labels([_folder(), _folder(feature_set="mine")], [a, b]) == ["paper8", "mine"]
    assert folder_labels([_folder(), _folder(dataset="nln")], [a, b]) == ["pump", "nln"]
    assert folder_labels([_folder(), _folder()], [a, b]) == ["a", "b"]
    same = [Path("x/out"), Path("y/out")]
    assert folder_labels([_folder(), _folder()], same) == ["x/out", "y/out"]


def test_runs_pair_by_cell_and_repetition_and_the_second_folder_is_compared():
    pair = pair_folders([_folder(), _folder(-0.1, feature_set="float16")], [Path("a"), Path("b")])
    assert pair.labels == ("paper8", "float16") and pair.baseline == "paper8"
    assert pair.table_name == "comparison_vs_a.csv"
    assert pair.per_recording is None  # neither folder has per-recording counts
    comparison = pair.compare(margin=0.02)
    cells = comparison.table[comparison.table["level"] == "cell"]
    # every run of b is its partner's Macro F1 minus 0.1 exactly: each cell, each sensor
    assert len(cells) == len(CELLS) and set(cells["candidate"]) == {"float16"}
    assert cells["delta"].to_numpy() == pytest.approx(-0.1)
    assert set(cells["label"]) == {"worse"}


def test_the_baseline_is_one_folder_and_per_recording_needs_both():
    results, paths = [_folder(), _folder(0.05, dataset="nln")], [Path("a"), Path("b")]
    pair = pair_folders(results, paths, baseline="nln")
    assert pair.baseline == "nln"
    counts = pd.DataFrame({"machine": ["Motor-2"], "count": [1]})
    assert pair_folders(results, paths, per_recording=[counts, None]).per_recording is None
    both = pair_folders(results, paths, per_recording=[counts, counts]).per_recording
    assert list(both["source"]) == ["pump", "nln"]
    with pytest.raises(SDTError, match=r"must be one of \['pump', 'nln'\], got 'adxl345'"):
        pair_folders(results, paths, baseline="adxl345")
