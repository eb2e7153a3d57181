"""Sizes checked before allocating: ``validate-noise --windows`` and ``dataset synth --duration``.

On main before the reliability round ``sdt validate-noise --windows 1000000000``
asked numpy for 100 TB (a MemoryError traceback, or swapping) and
``sdt dataset synth --duration 1e6`` started generating. Now a size that cannot
fit is refused with its samples and bytes (even with ``--yes``), and a large or
long one needs ``--yes``. The estimates are checked against measurement.
"""

from __future__ import annotations

import tracemalloc
from pathlib import Path

import numpy as np
import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sdt_plugins.datasets.synthetic_pump.generate import FS_HZ, generate_run

from sdt_framework.data import write_nln_emp
from sdt_framework.registry import build_registry
from sdt_framework.validation import noise_check


@pytest.mark.parametrize("yes", [[], ["--yes"]])
def test_noise_check_that_cannot_fit_is_refused(
    sdt_main, monkeypatch, capsys, yes: list[str]
) -> None:
    args = ["validate-noise", "--sensor", "adxl345", "--windows", "1000000000", *yes]
    code, _, err = sdt_main(*args)
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err
    # 10^9 windows x 2048 samples at 3200 Hz <- 20 kHz: 6.4x as many input samples
    assert "12,799,999,999,995 samples" in err and "TB of memory" in err
    assert "more than the" in err and "--yes" not in err


def test_large_noise_check_needs_yes(sdt_main, monkeypatch, capsys) -> None:
    monkeypatch.setattr("sdt_framework.cli.guards.LONG_SECONDS", 0.0)
    code, _, err = sdt_main("validate-noise", "--sensor", "adxl345")
    # (8 x 2048 - 1) x 20000 / 3200 + 1 input samples give 8 x 2048 outputs at 3200 Hz
    assert code == 2 and "pass --yes to run it" in err and "102,395 samples" in err
    code, out, err = sdt_main("validate-noise", "--sensor", "adxl345", "--yes")
    assert code == 0 and "Noise RMS" in out, err


@pytest.mark.parametrize("yes", [[], ["--yes"]])
def test_synth_that_cannot_fit_is_refused(
    sdt_main, monkeypatch, capsys, tmp_path: Path, yes
) -> None:
    out = tmp_path / "syn"
    args = ["dataset", "synth", "--out", str(out), "--duration", "1e6", *yes]
    code, _, err = sdt_main(*args)
    assert code == 2 and err.count("\n") == 1
    assert "5,100,000,000,000 samples" in err and "more than the" in err  # 255 x 1e6 s x 20 kHz
    assert not out.exists()


def test_long_synth_needs_yes(sdt_main, monkeypatch, capsys, tmp_path: Path) -> None:
    monkeypatch.setattr("sdt_framework.cli.guards.LONG_SECONDS", 0.0)
    args = ["dataset", "synth", "--out", str(tmp_path / "syn"), "--duration", "0.25"]
    code, _, err = sdt_main(*args)
    assert code == 2 and "1,275,000 samples" in err and "pass --yes" in err
    assert not (tmp_path / "syn").exists()
    code, _, err = sdt_main(*args, "--yes")
    assert code == 0 and "wrote 255 files" in err


def test_synth_disk_estimate_matches_what_is_written(tmp_path: Path) -> None:
    from sdt_framework.data.sizes import synth_cost

    dataset = open_synthetic(duration=0.5, acquisitions=3, machines="Motor-2", channels="ch1")
    written = sum(p.stat().st_size for p in write_nln_emp(dataset, tmp_path))
    estimate = synth_cost(len(dataset.recordings()), 1, 3, 0.5, FS_HZ).disk_bytes
    assert 0.8 < estimate / written < 1.5, (estimate, written)


def test_synth_memory_estimate_bounds_the_measured_peak() -> None:
    from sdt_framework.data.sizes import synth_cost

    duration = 0.5
    tracemalloc.start()
    channels = ("ch1", "ch2", "ch3", "ch4", "ch5")
    generate_run(
        "Motor-4",
        "cavitation suction",
        4,
        channels=channels,
        acquisitions=1,
        duration_s=duration,
        seed=0,
    )
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    n = len(open_synthetic(duration=duration).recordings())
    estimate = synth_cost(n, 5, 1, duration, FS_HZ).memory_bytes
    assert peak < estimate < 3 * peak, (peak, estimate)


def test_synth_memory_estimate_bounds_the_peak_of_writing_kept_runs_included(tmp_path) -> None:
    """Writing reads every run through the dataset, which keeps the runs it generated
    (4.8 MB here, all of them): the estimate counts them beside the run being made. The
    seed is this test's own, so no run is kept already from another test."""
    from sdt_framework.data.sizes import synth_cost

    dataset = open_synthetic(duration=0.5, machines="Motor-2", seed=20261129)
    n = len(dataset.recordings())
    tracemalloc.start()
    write_nln_emp(dataset, tmp_path)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    kept = 8 * n * round(0.5 * FS_HZ)
    assert dataset.kept_at_most(n * round(0.5 * FS_HZ)) == kept  # under its 64 MB
    estimate = synth_cost(n, 5, 1, 0.5, FS_HZ, kept).memory_bytes
    assert peak > kept  # the kept runs are in the peak
    assert peak < estimate < 3 * peak, (peak, estimate)


@pytest.mark.parametrize("sensor", ["adxl345", "adxl357", "wilcoxon-786b10"])
def test_noise_memory_estimate_bounds_the_measured_peak(sensor: str) -> None:
    from sdt_framework.validation.noise_check import zero_motion_cost

    spec = build_registry().sensor(sensor)
    n_in, estimate, _ = zero_motion_cost(spec, 20000.0, 32, 2048)
    tracemalloc.start()
    result = noise_check(spec, n_windows=32, window_length=2048)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert result.input_samples == n_in
    assert peak < estimate < 3 * peak, (peak, estimate)
    assert np.isfinite(result.sdt.rms_mg).all()
