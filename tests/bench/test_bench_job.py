"""``bench.run_benchmark_folder``: the main job as one call, as ``sdt benchmark`` runs it.

Checked against what the call must do, not against its own code: the runs a
configuration asks for (counted from the configuration), the files of a
results folder, the order of the caller's steps and the folder's lock at each,
nothing written for a plan refused by its size or by the caller's check, and
a second call resuming every run with the same tables.
"""

from __future__ import annotations

import os
import subprocess
import sys

import pandas as pd
import pytest

from sdt_framework import SDTError
from sdt_framework.bench import OUTPUT_FILES, run_benchmark_folder
from sdt_framework.bench.folder_lock import holds_results_folder, lock_results_folder


def _runs(config) -> int:
    """Runs a synthetic-pump configuration asks for: one per cell and repetition."""
    cells = len(config.machines) * len(config.scenarios) * len(config.sensors)
    return cells * len(config.classifiers) * config.repeats


def test_one_call_writes_the_folder_the_command_writes(small_config, registry, tmp_path):
    config = small_config()
    out = tmp_path / "out"
    run = run_benchmark_folder(config, registry, out)
    assert {p.name for p in out.iterdir()} >= {*OUTPUT_FILES, ".sdt-results.json", "runs"}
    assert len(run.results) == _runs(config) == 24 == len(list((out / "runs").glob("*.json")))
    assert run.failed == 0 and run.result.runs_computed == 24
    on_disk = pd.read_parquet(out / "results.parquet")
    pd.testing.assert_frame_equal(on_disk, run.results.reset_index(drop=True), check_dtype=False)
    # Table 4: one block per scenario, the plan's sensors in its order
    table = run.table4()
    assert [b.scenario for b in table.blocks] == ["forward", "backward", "interpolation"]
    assert all(b.sensors == ("wilcoxon-786b10", "adxl345") for b in table.blocks)
    assert not holds_results_folder(out)


def test_the_caller_steps_come_in_order_and_the_report_step_holds_the_lock(
    small_config, registry, tmp_path
):
    out = tmp_path / "out"
    seen: list[str] = []

    def check(plan):
        seen.append(f"check {len(plan.recordings)} recordings, folder exists: {out.exists()}")

    def started(plan, size):
        seen.append(f"started {size.runs_to_do} runs, locked: {holds_results_folder(out)}")

    def finish(run):
        written = (out / "summary.json").is_file()
        seen.append(f"finish, outputs written: {written}, locked: {holds_results_folder(out)}")
        # another process cannot take the folder while the report is written
        probe = (
            "import sys; from sdt_framework.bench.folder_lock import lock_results_folder as f\n"
            "try:\n    f(sys.argv[1])\nexcept Exception as e:\n    print(e)"
        )
        done = subprocess.run(
            [sys.executable, "-c", probe, str(out)], capture_output=True, text=True, check=True
        )
        seen.append(f"other process: {'in use' in done.stdout}")

    run_benchmark_folder(small_config(), registry, out, check=check, started=started, finish=finish)
    # 15 Motor-2 runs x 2 channels
    assert seen == [
        "check 30 recordings, folder exists: False",
        "started 24 runs, locked: True",
        "finish, outputs written: True, locked: True",
        "other process: True",
    ]
    assert not holds_results_folder(out)


def test_a_refusing_check_or_size_writes_nothing(small_config, registry, tmp_path, monkeypatch):
    out = tmp_path / "out"

    def refuse(plan):
        raise SDTError("no zone table for Motor-2")

    with pytest.raises(SDTError, match="no zone table"):
        run_benchmark_folder(small_config(), registry, out, check=refuse)
    assert not out.exists()
    monkeypatch.setattr("sdt_framework.bench.estimate.CONFIRM_ABOVE_SECONDS", 0.0)
    with pytest.raises(SDTError, match=r"^this benchmark is 24 runs .*; add --yes to start it"):
        run_benchmark_folder(small_config(), registry, out)
    assert not out.exists()
    assert run_benchmark_folder(small_config(), registry, out, yes=True).failed == 0


def test_a_second_call_resumes_every_run_and_a_held_lock_stays_held(
    small_config, registry, tmp_path
):
    out = tmp_path / "out"
    first = run_benchmark_folder(small_config(), registry, out)
    os.makedirs(out, exist_ok=True)
    lock_results_folder(out)  # the caller holds the folder before the call
    again = run_benchmark_folder(small_config(), registry, out)
    assert (again.result.runs_computed, again.result.runs_resumed) == (0, 24)
    assert again.size.runs_to_do == 0  # the stored runs are not counted in the estimate
    pd.testing.assert_frame_equal(
        again.results.drop(columns="fit_seconds"), first.results.drop(columns="fit_seconds")
    )
    assert holds_results_folder(out)
