"""``sdt compare`` never changes a verdict silently when its inputs are incomplete.

Without the recording-level interval a cell's label rests on the repetition
interval alone, and on this small folder that moves labels (inconclusive
becomes worse, checked below). So a ``per_recording.parquet`` that lacks the
counts of some runs, or cannot be read, is refused with one line naming the
file and the command that rewrites it; a folder without the file at all is
compared with a warning saying the labels use repetitions only; runs without
a partner are named, never dropped without a word.
"""

from __future__ import annotations

import json
import shutil

import pandas as pd
import pytest

from sdt_framework import build_registry
from sdt_framework.bench import BenchmarkConfig, run_benchmark_folder
from sdt_framework.bench.results import RUN_COLUMNS

from .conftest import SMALL


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    """A small complete folder (reference and adxl345, lr and knn, 2 repeats): 24 runs."""
    root = tmp_path_factory.mktemp("compare")
    config = BenchmarkConfig(
        **{**SMALL, "sensors": ["wilcoxon-786b10", "adxl345"], "cache_dir": str(root / "cache")}
    )
    run_benchmark_folder(config, build_registry(), root / "a")
    return root / "a"


@pytest.fixture
def folder(built, tmp_path):
    """A fresh copy of the complete folder, for one test to damage."""
    return shutil.copytree(built, tmp_path / "a")


def labels(sdt_main, *args: str) -> tuple[pd.DataFrame, str]:
    code, out, err = sdt_main("compare", *args, "--json")
    assert code == 0, err
    return pd.DataFrame(json.loads(out)["table"]), err


def one_error_line(code: int, err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2 and len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def test_per_recording_missing_a_runs_rows_is_refused_and_resuming_repairs_it(folder, sdt_main):
    complete, err = labels(sdt_main, str(folder))
    assert err == ""
    rows = pd.read_parquet(folder / "per_recording.parquet")
    run = rows.iloc[0][RUN_COLUMNS]
    dropped = rows[~(rows[RUN_COLUMNS] == run).all(axis=1)]
    assert len(dropped) < len(rows)
    dropped.to_parquet(folder / "per_recording.parquet")
    (folder / "comparison.csv").unlink()

    line = one_error_line(*sdt_main("compare", str(folder))[::2])
    assert line.startswith(
        f"error: {folder / 'per_recording.parquet'} lacks the counts of 1 of the 24 runs"
    )
    assert f"machine=Motor-2 scenario={run['scenario']} sensor={run['sensor']}" in line
    assert f"resuming (sdt benchmark {folder / 'config.toml'} --out {folder}" in line
    assert not (folder / "comparison.csv").exists()

    code, _, err = sdt_main("benchmark", str(folder / "config.toml"), "--out", str(folder))
    assert code == 0, err  # the advice: every run is resumed and every file rewritten
    repaired, err = labels(sdt_main, str(folder))
    pd.testing.assert_frame_equal(repaired, complete)


def test_a_truncated_per_recording_file_is_refused(folder, sdt_main):
    path = folder / "per_recording.parquet"
    path.write_bytes(path.read_bytes()[: path.stat().st_size // 2])
    line = one_error_line(*sdt_main("compare", str(folder))[::2])
    assert line.startswith(f"error: {path} cannot be read (")
    assert "or delete it to compare on the repetition intervals only" in line


def test_without_per_recording_the_labels_change_and_a_warning_says_so(folder, sdt_main):
    complete, _ = labels(sdt_main, str(folder))
    (folder / "per_recording.parquet").unlink()
    partial, err = labels(sdt_main, str(folder))
    assert err.strip() == (
        f"warning: {folder / 'per_recording.parquet'} is missing: the labels rest on the "
        f"repetition intervals only (no recording-level intervals)"
    )
    # why a silent drop is wrong: on this folder some label does move
    assert (partial["label"] != complete["label"]).any()


def test_two_folders_name_the_runs_that_have_no_partner(folder, tmp_path, sdt_main):
    other = shutil.copytree(folder, tmp_path / "b")
    results = pd.read_parquet(other / "results.parquet")
    gone = results.iloc[5]
    results = results.drop(index=5)
    results.to_parquet(other / "results.parquet")
    results.to_csv(other / "results.csv", index=False)
    rows = pd.read_parquet(other / "per_recording.parquet")
    rows[~(rows[RUN_COLUMNS] == gone[RUN_COLUMNS]).all(axis=1)].to_parquet(
        other / "per_recording.parquet"
    )

    table, err = labels(sdt_main, str(folder), str(other))
    where = " ".join(
        f"{k}={gone[k]}" for k in ("machine", "scenario", "sensor", "classifier", "repeat")
    )
    assert err.strip() == (
        "warning: 1 run left out of the comparison, its partner has no successful run: "
        f"a: {where} has no partner in b"
    )
    cell = table[(table["level"] == "cell") & (table["sensor"] == gone["sensor"])]
    cell = cell[(cell["scenario"] == gone["scenario"]) & (cell["classifier"] == gone["classifier"])]
    assert cell["n_repeats"].tolist() == [1]  # 2 repeats, one of them unpaired
