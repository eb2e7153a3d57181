"""``--units`` is part of the benchmark's size: estimated first, refused if it cannot fit.

On main before round 2, ``sdt benchmark --quick --units 1000000`` printed no
estimate, needed no ``--yes``, claimed the results folder and grew memory
(~25 MB/s) until the kernel killed it: the estimate ignored ``--units``.
"""

from __future__ import annotations

import pytest

from sdt_framework.bench.config import load_config
from sdt_framework.bench.estimate import BLOCK_BYTES, estimate
from sdt_framework.bench.plan import plan_benchmark


@pytest.fixture
def no_run(monkeypatch):
    """Starting the benchmark fails the test (so old code cannot grow memory here)."""

    def refuse(*args, **kwargs):
        pytest.fail("the benchmark started before its size was checked")

    monkeypatch.setattr("sdt_framework.bench.runner.run_benchmark", refuse)


def test_units_multiply_the_runs_draws_and_memory(registry):
    nominal = estimate(plan_benchmark(load_config(None, {"quick": True}), registry))
    drawn = estimate(plan_benchmark(load_config(None, {"quick": True, "units": 7}), registry))
    # every run is repeated per unit: 2 machines x 3 scenarios x 3 sensors x 5 classifiers
    # x 2 repeats x 7 units
    assert drawn.runs == 180 * 7 == 7 * nominal.runs
    # 255 recordings: adxl345 and adxl357 (noisy, with tolerances) 2 repeats x 7 units each;
    # the reference (noise-free, no tolerances) once, shared by every unit and repeat
    assert drawn.feature_draws == 255 * (2 * 2 * 7 + 1)
    # each (recording, sensor, unit, repeat) is a feature block held until the end
    assert drawn.memory_bytes - nominal.memory_bytes >= 255 * 3 * 2 * 6 * BLOCK_BYTES
    assert drawn.seconds > 6 * nominal.seconds


def test_a_million_units_is_refused_before_the_folder_is_claimed(sdt_main, tmp_path, no_run):
    out = tmp_path / "out"  # without the check it would grow memory: no_run fails it instead
    code, _, err = sdt_main(
        "benchmark", "--quick", "--units", "1000000", "--yes", "--out", str(out)
    )
    assert code == 2, err
    line = err.strip()
    assert "\n" not in line and "Traceback" not in line
    # even --yes does not start what cannot fit; the line names --units and the size
    assert line.startswith(
        "error: this benchmark with --units 1000000 is 180000000 runs and 1020000255 "
        "featurised signals, estimated "
    )
    assert " TB of memory, more than the " in line and " available; lower --units" in line
    assert not out.exists()


def test_many_units_that_fit_need_yes(sdt_main, monkeypatch, tmp_path, no_run):
    monkeypatch.setattr("sdt_framework.signals.sizes.available_memory", lambda: 10**15)
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", "--quick", "--units", "1000", "--out", str(out))
    assert code == 2 and err.count("\n") == 1
    assert err.startswith("error: this benchmark with --units 1000 is 180000 runs")
    assert "add --yes to start it, or lower --units" in err
    assert not out.exists()


def test_a_full_disk_refuses_it(sdt_main, monkeypatch, tmp_path, no_run):
    monkeypatch.setattr("sdt_framework.signals.sizes.free_disk", lambda path: 1000)
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", "--quick", "--units", "3", "--out", str(out))
    assert code == 2 and err.count("\n") == 1
    assert "more than the 1.0 kB free on the disk of " in err and not out.exists()
