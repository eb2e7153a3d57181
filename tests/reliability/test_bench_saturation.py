"""A recording that mostly sits at a sensor's full scale is said so, in the terminal
summary and in summary.json (before: nothing, whatever share of samples was clipped)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

FS = 20_000
AMPLITUDE = 20.0  # g, on an adxl345 (+-16 g)


def _manifest(folder: Path) -> Path:
    """Healthy: 0.1 g noise; fault: a 20 g, 20 Hz sine (and its noise). 2 s each."""
    rng = np.random.default_rng(0)
    t = np.arange(2 * FS) / FS
    lines = ["path,sampling_rate_hz,machine,condition,severity,recording_id,channel"]
    for index in range(3):
        for condition, signal in (
            ("healthy", 0.1 * rng.normal(size=t.size)),
            (
                "fault",
                AMPLITUDE * np.sin(2 * np.pi * 20 * t + index) + 0.1 * rng.normal(size=t.size),
            ),
        ):
            name = f"{condition}{index}"
            np.save(folder / f"{name}.npy", signal)
            severity = index + 1 if condition == "fault" else ""
            lines.append(f"{name}.npy,{FS},m,{condition},{severity},{name},ch1")
    manifest = folder / "m.csv"
    manifest.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return manifest


def _run(sdt_main, manifest: Path, folder: Path) -> tuple[str, dict]:
    """``sdt benchmark --quick`` of adxl345 on ``manifest``: stderr, summary.json's entry."""
    out = folder / "out"
    code, _, err = sdt_main(
        "benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
        "--classifiers", "lr", "--out", str(out), "--cache-dir", str(folder / "cache"),
    )  # fmt: skip
    assert code == 0, err
    return err, json.loads((out / "summary.json").read_text())["saturation"]["adxl345"]


def test_saturated_recordings_are_named_with_their_share(sdt_main, tmp_path):
    manifest = _manifest(tmp_path)
    err, entry = _run(sdt_main, manifest, tmp_path)
    # a sine of amplitude A spends 1 - (2/pi) asin(16/A) of its time beyond +-16 g; the
    # chain's low-passes barely touch 20 Hz (|H| > 0.999), so A stays 20 g
    expected = 1 - 2 / math.pi * math.asin(16 / AMPLITUDE)
    assert entry["full_scale_g"] == 16.0
    assert entry["recordings"] == 6 and entry["recordings_above_limit"] == 3
    assert {w["recording_id"] for w in entry["worst"]} == {f"m/fault{i}/ch1" for i in range(3)}
    for worst in entry["worst"]:
        assert abs(worst["fraction"] - expected) < 0.01, worst
    assert abs(entry["fraction"] - expected / 2) < 0.01  # half the recordings are healthy
    lines = [line for line in err.splitlines() if "full scale (clipped)" in line]
    assert len(lines) == 1
    assert lines[0].startswith("warning: adxl345 is at its +-16 g full scale (clipped) in 3 of 6")
    assert f"{expected:.0%}" in lines[0]


def test_quiet_recordings_give_no_warning(sdt_main, tmp_path):
    manifest = _manifest(tmp_path)
    text = manifest.read_text().splitlines()
    manifest.write_text("\n".join(line for line in text if "fault" not in line) + "\n")
    for index in range(3):  # a second class, also quiet
        np.save(tmp_path / f"quiet{index}.npy", np.full(2 * FS, 0.5))
    with manifest.open("a") as handle:
        for index in range(3):
            handle.write(f"quiet{index}.npy,{FS},m,quiet,{index + 1},quiet{index},ch1\n")
    err, entry = _run(sdt_main, manifest, tmp_path)
    assert "full scale" not in err
    assert entry["fraction"] == 0.0 and entry["worst"] == []
