"""Benchmarks with catalogue parts, data at other rates, skipped sensors and sensor axes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from sdt_framework import build_registry
from sdt_framework.api import extract
from sdt_framework.bench.featurise import FeatureJob, featurise_recording
from sdt_framework.bench.plan import plan_benchmark
from sdt_framework.cli.main import app
from sdt_framework.data import open_manifest
from sdt_framework.errors import SDTError

pytestmark = pytest.mark.catalog


def write_manifest(folder: Path, fs: float, seconds: float = 1.5) -> Path:
    """A small dataset at ``fs`` Hz: three healthy runs and a fault at severities 1-3."""
    rng = np.random.default_rng(0)
    t = np.arange(int(seconds * fs)) / fs
    rows = []
    runs = [("healthy", "", i, 0.0) for i in (1, 2, 3)] + [("bearing", s, s, s) for s in (1, 2, 3)]
    for condition, severity, index, level in runs:
        run = f"{condition}-{index}"
        for acq in range(2):
            x = np.sin(2 * np.pi * 50 * t) + 0.3 * level * np.sin(2 * np.pi * 1200 * t)
            x = x + rng.normal(scale=0.05, size=t.size)
            np.save(folder / f"{run}-{acq}.npy", x)
            rows.append(f"{run}-{acq}.npy,{fs:g},{condition},{severity},{run},ch1")
    manifest = folder / "manifest.csv"
    header = "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
    manifest.write_text(header + "\n".join(rows) + "\n")
    return manifest


def test_data_at_12_khz_runs_with_the_default_set_and_the_reference_follows(tmp_path):
    manifest = write_manifest(tmp_path, 12000.0)
    out = tmp_path / "out"
    result = CliRunner().invoke(
        app,
        ["benchmark", "--data", str(manifest), "--quick", "--classifiers", "lr",
         "--scenarios", "forward", "--jobs", "1", "--no-report", "--out", str(out),
         "--cache-dir", str(tmp_path / "cache")],
        env={"COLUMNS": "120"},
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    results = pd.read_csv(out / "results.csv")
    assert set(results["sensor"]) == {"native-reference", "adxl345", "adxl357"}
    assert (results["status"] == "ok").all()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["reference"] == "native-reference" and summary["skipped_sensors"] == []
    # the reference's features are those of the recording itself (identity chain at 12 kHz)
    features = pd.read_parquet(out / "features.parquet")
    ref = features[(features["sensor"] == "native-reference") & (features["run"] == "bearing-3")]
    raw = np.stack([np.load(tmp_path / f"bearing-3-{a}.npy") for a in (0, 1)])
    table = extract(raw, 12000.0, build_registry().feature_set("paper8"))
    np.testing.assert_array_equal(ref[list(table.names)].to_numpy(), table.values)


def test_the_default_set_at_20_khz_is_the_papers(small_config, registry):
    plan = plan_benchmark(small_config(sensors=None), registry)
    assert [s.name for s in plan.sensors] == ["wilcoxon-786b10", "adxl345", "adxl357"]
    assert plan.reference == "wilcoxon-786b10" and plan.skipped_sensors == {}


def test_parts_faster_than_the_data_are_skipped_with_their_reason(small_config, registry):
    plan = plan_benchmark(
        small_config(sensors=["adxl355", "iis3dwb[range=4g]", "mpu6050"]), registry
    )
    assert [s.name for s in plan.sensors] == [
        "adxl355[odr=4000,range=2g]",
        "mpu6050[dlpf=260,range=2g]",
    ]
    [(name, reason)] = plan.skipped_sensors.items()
    assert name == "iis3dwb[axes=xyz,lpf2=off,range=4g]"
    assert "samples at 26667 Hz, above the data's 20000 Hz" in reason


def test_nothing_left_to_run_is_an_error(small_config, registry):
    with pytest.raises(SDTError, match=r"no sensor can be simulated from this data.*26667 Hz"):
        plan_benchmark(small_config(sensors=["iis3dwb"]), registry)


def test_two_names_for_one_sensor_are_rejected(small_config, registry):
    with pytest.raises(SDTError, match="'adxl355' and 'adxl355\\[range=2g\\]' are both"):
        plan_benchmark(small_config(sensors=["adxl355", "adxl355[range=2g]"]), registry)


def test_axes_must_name_channels_of_the_data(small_config, registry):
    with pytest.raises(SDTError, match="unknown channel\\(s\\) in axes \\['ch9'\\]"):
        plan_benchmark(small_config(axes={"ch9": "z"}), registry)


def test_a_channel_on_the_z_axis_gets_the_z_noise(tmp_path, registry, readers):
    """ADXL345: 290 ug/sqrt(Hz) on X, 430 on Z (datasheet p. 33); zero motion shows the ratio."""
    fs = 20000.0
    np.save(tmp_path / "zero.npy", np.zeros((4, int(2 * fs))))
    (tmp_path / "m.csv").write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
        f"zero.npy,{fs:g},healthy,,r1,ch1\n"
    )
    [recording] = open_manifest(tmp_path / "m.csv", readers=readers).recordings()
    part = registry.sensor("adxl345-ds")
    feature_set = registry.feature_set("paper8")

    def sigma(axis: str) -> float:
        job = FeatureJob(recording, "k", (part,), feature_set, 1, 0, 0.64, 0.1, None, axis)
        [block] = featurise_recording(job).blocks
        assert block.sensor == part.name  # the axis changes the figures, not the name
        return float(np.mean(block.values[:, 0]))

    # the same noise draws on both axes (common random numbers), scaled by the density;
    # the 13-bit step (3.9 mg, 1.1 mg rms) adds a little to both
    step = part.quantisation_step_g / np.sqrt(12)
    expected = np.hypot(430e-6 * np.sqrt(1600), step) / np.hypot(290e-6 * np.sqrt(1600), step)
    assert sigma("z") / sigma("x") == pytest.approx(expected, rel=0.02)
