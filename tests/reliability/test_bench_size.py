"""A benchmark that would take hours says so, with its size, and starts only with --yes."""

from __future__ import annotations

import re

from typer.testing import CliRunner

from sdt_framework.bench.config import load_config
from sdt_framework.bench.plan import plan_benchmark
from sdt_framework.cli.main import app


def test_the_size_is_counted_from_the_plan(registry):
    from sdt_framework.bench.estimate import estimate

    quick = plan_benchmark(load_config(None, {"quick": True}), registry)
    size = estimate(quick)
    # 2 machines x 3 scenarios x 3 sensors x 5 classifiers x 2 repeats
    assert size.runs == 180
    # every recording: 2 noisy sensors x 2 repeats + the reference once
    assert size.feature_draws == len(quick.recordings) * (2 * 2 + 1)
    bigger = estimate(plan_benchmark(load_config(None, {"quick": True, "repeats": 20}), registry))
    assert bigger.runs == 1800 and bigger.seconds > 5 * size.seconds
    assert estimate(quick, stored_runs=90).runs_to_do == 90


def test_hours_of_work_need_yes(tmp_path, monkeypatch, sdt_main):
    # 5000 repeats hold ~150 GB of features: room is made so that only the time is at stake
    # (tests/reliability/test_bench_size_units.py: a size that cannot fit is refused)
    monkeypatch.setattr("sdt_framework.signals.sizes.available_memory", lambda: 10**15)
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", "--quick", "--repeats", "5000", "--out", str(out))
    assert code == 2
    line = err.strip()
    # 180 runs per 2 repeats; 255 recordings x (2 noisy sensors x 5000 repeats + reference)
    assert line.startswith("error: this benchmark is 450000 runs and 2550255 featurised signals")
    assert re.search(r", estimated [\d.]+ (h|days) on \d+ process", line)
    assert line.endswith(
        "add --yes to start it, or lower --repeats or select fewer sensors, classifiers or machines"
    )
    assert "\n" not in line and not out.exists()


def test_yes_starts_it(monkeypatch, tmp_path):
    from sdt_framework.bench import estimate as estimate_module

    monkeypatch.setattr(estimate_module, "CONFIRM_ABOVE_SECONDS", 0.0)  # anything is "long"
    args = ["benchmark", "--quick", "--machines", "Motor-2", "--sensors", "adxl345"]
    args += ["--classifiers", "lr", "--channels", "ch1", "--jobs", "1", "--no-report"]
    args += ["--cache-dir", str(tmp_path / "cache")]
    refused = CliRunner().invoke(app, [*args, "--out", str(tmp_path / "a")])
    assert "add --yes to start it" in str(refused.exception)
    started = CliRunner().invoke(app, [*args, "--out", str(tmp_path / "b"), "--yes"])
    assert started.exit_code == 0, started.output
    # 3 scenarios x 2 repeats; 15 Motor-2 recordings of ch1 x 2 repeats of adxl345
    assert started.stderr.startswith("note: this benchmark is 6 runs and 30 featurised signals")
    assert (tmp_path / "b" / "results.csv").exists()
