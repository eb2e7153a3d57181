"""sdt explore end to end on a small synthetic protocol: files, equality with benchmark, Dask."""

from __future__ import annotations

import textwrap

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sdt_framework import build_registry
from sdt_framework.bench import BenchmarkConfig, plan_benchmark, run_benchmark, run_plan_folder
from sdt_framework.cli.main import app
from sdt_framework.explore.output import EXPLORE_FILES, write_explore
from sdt_framework.explore.run import explore_table, plan_explore
from sdt_framework.explore.sweep_file import parse_sweep

from ..helpers import small_protocol

PROTOCOL = small_protocol(channels=2, repeats=2, scenarios=2)
SWEEP = {
    "base": "adxl345",
    "axes": {
        "sampling_rate_hz": {"levels": [1600, 3200]},
        "noise_density_ug_rthz": {"levels": [90, 290]},
    },
    "ties": {"digital_cutoff_hz": "rate / 2 - 1"},
    "target": {"max_loss": 0.1},
}


def run_explore(tmp_path, protocol=None, name="out"):
    registry = build_registry()
    protocol = {**PROTOCOL, "cache_dir": str(tmp_path / "cache"), **(protocol or {})}
    explore = plan_explore(parse_sweep(SWEEP), protocol, {}, registry)
    out = tmp_path / name
    run = run_plan_folder(explore.plan, out)
    result, table = run.result, explore_table(explore, run.results)
    write_explore(explore, table, out)
    return explore, result, table, out


def test_a_point_equal_to_adxl345_reproduces_its_benchmark_exactly(tmp_path):
    explore, result, table, _ = run_explore(tmp_path)
    point = "adxl345~rate=3200,nsd=290"
    assert point in {p.spec.name for p in explore.points}
    config = BenchmarkConfig(
        **{**PROTOCOL, "cache_dir": str(tmp_path / "cache2"), "sensors": ["adxl345"]}
    )
    bench = run_benchmark(plan_benchmark(config, build_registry()), tmp_path / "bench")
    names = list(explore.plan.feature_set.feature_names)
    ours = result.features[result.features["sensor"] == point]
    theirs = bench.features[bench.features["sensor"] == "adxl345"]
    assert np.array_equal(ours[names].to_numpy(), theirs[names].to_numpy())  # bit-identical
    mine = table[table["point"] == point].sort_values(["scenario", "repeat"])
    ref = pd.DataFrame([r.labels | {"macro_f1": r.macro_f1} for r in bench.runs])
    ref = ref.sort_values(["scenario", "repeat"])
    assert mine["macro_f1"].tolist() == ref["macro_f1"].tolist()


def test_explore_writes_every_file_and_the_report_section(tmp_path):
    _, _, table, out = run_explore(tmp_path, {"report": True})
    for name in EXPLORE_FILES:
        assert (out / name).exists(), name
    assert set(table["role"]) == {"reference", "base", "point"}
    assert len(table[table["role"] == "point"]) == 4 * 2 * 2  # points x scenarios x repeats
    parquet = pd.read_parquet(out / "explore.parquet")
    assert {"sampling_rate_hz", "noise_density_ug_rthz", "macro_f1", "point"} <= set(parquet)
    from sdt_framework.report import write_report

    write_report(out, ["md"])
    text = (out / "report.md").read_text()
    assert "## Exploration" in text
    assert "explore_main_effects.png" in text and "explore_pareto.png" in text


def test_explore_on_a_local_dask_cluster_equals_the_local_run(tmp_path):
    from distributed import LocalCluster

    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster:
        _, _, on_dask, _ = run_explore(
            tmp_path,
            {
                "backend": "dask",
                "scheduler": cluster.scheduler_address,
                "cache_dir": str(tmp_path / "dask-cache"),
            },
            name="dask",
        )
    _, _, local, _ = run_explore(tmp_path, name="local")
    columns = ["point", "machine", "scenario", "classifier", "repeat", "macro_f1"]
    pd.testing.assert_frame_equal(
        on_dask[columns].reset_index(drop=True), local[columns].reset_index(drop=True)
    )


def test_cli_example_prints_a_sweep_that_loads(tmp_path):
    result = CliRunner().invoke(app, ["explore", "--example"])
    assert result.exit_code == 0
    path = tmp_path / "example.toml"
    path.write_text(result.output)
    from sdt_framework.explore import load_sweep

    sweep, _ = load_sweep(path)
    assert sweep.base == "adxl345" and "sampling_rate_hz" in sweep.axes


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ('[sweep]\nbase = "nope"\n[sweep.axes]\nadc_bits = { levels = [12] }', "unknown sensor"),
        (
            '[sweep]\nbase = "adxl345"\n[sweep.axes]\nadc_bits = { levels = [12] }\n'
            '[benchmark]\nsensors = ["adxl357"]',
            "benchmark.sensors is set by the sweep",
        ),
        (
            '[sweep]\nbase = "adxl345"\n[sweep.axes]\nadc_bits = { levels = [12] }\n'
            "[benchmark]\nrepeats = -1",
            "repeats",
        ),
        ("[sweeps]\n", "unknown table"),
    ],
)
def test_cli_bad_sweeps_are_one_line_before_any_work(sdt_in_process, tmp_path, body, message):
    path = tmp_path / "sweep.toml"
    path.write_text(textwrap.dedent(body))
    out = tmp_path / "out"
    result = sdt_in_process("explore", str(path), "--out", str(out))  # refused before any work
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error:") and message in lines[0], lines
    assert not out.exists()
