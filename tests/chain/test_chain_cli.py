"""``sdt degrade`` and ``sdt validate-noise`` through the real entry point."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.cli.main import main


def run(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], *args: str):
    monkeypatch.setattr(sys, "argv", ["sdt", *args])
    code = 0
    try:
        main()
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 1
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.fixture
def signal(tmp_path: Path) -> Path:
    t = np.arange(24000) / 20000
    x = np.vstack([np.sin(2 * np.pi * 60 * t), 0.2 * np.cos(2 * np.pi * 900 * t)])
    path = tmp_path / "sig.npy"
    np.save(path, x)
    return path


def test_degrade_npy_writes_output_and_summary(monkeypatch, capsys, signal, tmp_path) -> None:
    out = tmp_path / "o.npy"
    code, stdout, _ = run(
        monkeypatch,
        capsys,
        "degrade",
        str(signal),
        "--sensor",
        "adxl345",
        "--fs",
        "20000",
        "--seed",
        "3",
        "--out",
        str(out),
    )
    assert code == 0
    y = np.load(out)
    assert y.shape == (2, 3840) and y.dtype == np.float64
    assert "3200 Hz" in stdout and "2 x 3840" in stdout


def test_degrade_csv_round_trip_matches_python(monkeypatch, capsys, signal, tmp_path) -> None:
    from sdt_framework.api import degrade
    from sdt_framework.registry import build_registry

    x = np.load(signal)
    src, out = tmp_path / "in.csv", tmp_path / "out.csv"
    np.savetxt(src, x, delimiter=",", fmt="%.17g")
    code, _, _ = run(
        monkeypatch,
        capsys,
        "degrade",
        str(src),
        "--sensor",
        "adxl357",
        "--fs",
        "20000",
        "--out",
        str(out),
        "--no-noise",
    )
    assert code == 0
    expected, _ = degrade(x, 20000, build_registry().sensor("adxl357"), noise=False)
    np.testing.assert_array_equal(np.loadtxt(out, delimiter=","), expected)


@pytest.mark.parametrize(
    ("content", "fs", "needle"),
    [
        # refused by the NPY reader as it reads the file, as a manifest row is
        ("nan", "20000", "acquisition 0, sample 1: non-finite value"),
        ("inf", "20000", "acquisition 0, sample 1: non-finite value"),
        ("empty", "20000", "holds no samples"),
        ("cube", "20000", "array of shape (2, 2, 2); expected 1-D or 2-D"),
        # refused by the chain, naming the sensor
        ("ok", "1000", "adxl345', recording"),
        ("ok", "1000", "target rate 3200 Hz is above the recording's rate 1000 Hz"),
    ],
)
def test_degrade_user_errors_exit_2_with_one_line(
    monkeypatch, capsys, tmp_path, content: str, fs: str, needle: str
) -> None:
    data = {
        "nan": np.array([0.0, np.nan, 1.0]),
        "inf": np.array([0.0, np.inf]),
        "empty": np.zeros(0),
        "cube": np.zeros((2, 2, 2)),
        "ok": np.zeros(100),
    }[content]
    src = tmp_path / f"{content}.npy"
    np.save(src, data)
    code, _, err = run(
        monkeypatch,
        capsys,
        "degrade",
        str(src),
        "--sensor",
        "adxl345",
        "--fs",
        fs,
        "--out",
        str(tmp_path / "o.npy"),
    )
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert needle in err and src.name in err
    assert not (tmp_path / "o.npy").exists()


def test_unknown_sensor_exits_2(monkeypatch, capsys, signal, tmp_path) -> None:
    code, _, err = run(
        monkeypatch,
        capsys,
        "degrade",
        str(signal),
        "--sensor",
        "adxl999",
        "--fs",
        "20000",
        "--out",
        str(tmp_path / "o.npy"),
    )
    assert code == 2 and "unknown sensor 'adxl999'" in err and "Traceback" not in err


def test_validate_noise_json_meets_the_done_criterion(monkeypatch, capsys) -> None:
    code, stdout, _ = run(monkeypatch, capsys, "validate-noise", "--sensor", "adxl345", "--json")
    assert code == 0
    data = json.loads(stdout)
    assert abs(data["sdt"]["rms_mg"] / 11.67 - 1) < 0.01
    assert abs(data["sdt"]["nsd_ug_rthz"] / 292.2 - 1) < 0.02


def test_validate_noise_with_lsb_recording_table_and_plot(monkeypatch, capsys, tmp_path) -> None:
    lsb = np.round(np.random.default_rng(1).normal(5, 3.2, 16384))  # ~12.5 mg at 3.9 mg/LSB
    rec = tmp_path / "rec.csv"
    np.savetxt(rec, lsb, fmt="%d", header="x", comments="")
    png = tmp_path / "noise.png"
    args = [
        "validate-noise",
        "--sensor",
        "adxl345",
        "--recording",
        str(rec),
        "--unit",
        "lsb",
        "--scale",
        "0.0039",
        "--fs",
        "3200",
        "--plot",
        str(png),
    ]
    code, stdout, _ = run(monkeypatch, capsys, *args)
    assert code == 0 and "Relative" in stdout and "Noise RMS" in stdout and "p < 0.001" in stdout
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    code, stdout, _ = run(
        monkeypatch, capsys, *[a for a in args if a != "--plot" and a != str(png)], "--json"
    )
    data = json.loads(stdout)
    assert data["recording"]["rms_mg"] == pytest.approx(3.2 * 3.9, rel=0.03)
    assert {"rms", "nsd"} <= set(data["p_value"]) and {"rms", "nsd"} <= set(
        data["relative_error_pct"]
    )


def test_validate_noise_lsb_without_scale_is_a_user_error(monkeypatch, capsys, tmp_path) -> None:
    rec = tmp_path / "rec.npy"
    np.save(rec, np.zeros(16384))
    code, _, err = run(
        monkeypatch,
        capsys,
        "validate-noise",
        "--sensor",
        "adxl345",
        "--recording",
        str(rec),
        "--unit",
        "lsb",
    )
    assert code == 2 and "--scale" in err


def test_validate_noise_allan_table_has_configured_and_read_off_columns(monkeypatch, capsys):
    code, stdout, _ = run(monkeypatch, capsys, "validate-noise", "--sensor", "adxl345")
    assert code == 0 and "Allan deviation, adxl345, x axis" in stdout
    assert "Configured" in stdout and "SDT model" in stdout and "290.0" in stdout
    row = next(line for line in stdout.splitlines() if "Bias instability" in line)
    assert row.split("│")[2].strip() == "-" and "n/a (1)" in row  # no term configured, none read
    assert "(1) SDT model: no flat region" in stdout and "tau 0.000313-0.256 s" in stdout
    code, stdout, _ = run(monkeypatch, capsys, "validate-noise", "--sensor", "adxl345", "--json")
    allan = json.loads(stdout)["allan"]
    assert allan["configured"]["nsd_ug_rthz"] == pytest.approx(290.0)
    assert allan["configured"]["bias_instability_ug"] is None
    # 290 ug/sqrt(Hz) and the 3.9 mg step's D^2/12 (28 ug/sqrt(Hz) at 3200 Hz), in power
    assert allan["sdt"]["nsd_ug_rthz"] == pytest.approx(math.hypot(290, 28.2), rel=0.02)
    assert allan["sdt"]["bias_instability_ug"] is None and allan["sdt"]["bias_reason"]


def test_validate_noise_recording_gets_its_own_allan_column(monkeypatch, capsys, tmp_path):
    lsb = np.round(np.random.default_rng(1).normal(5, 3.2, 20000))
    rec = tmp_path / "rec.csv"
    np.savetxt(rec, lsb, fmt="%d", header="x", comments="")
    args = ["validate-noise", "--sensor", "adxl345", "--recording", str(rec), "--unit", "lsb"]
    args += ["--scale", "0.0039", "--fs", "3200"]
    code, stdout, _ = run(monkeypatch, capsys, *args)
    allan_part = stdout[stdout.index("Allan deviation") :]
    assert code == 0 and "Recording" in allan_part and "Recording: 20,000 samples" in allan_part
    code, stdout, _ = run(monkeypatch, capsys, *args, "--json")
    recording = json.loads(stdout)["allan"]["recording"]
    # white: sqrt(3.2^2 + 1/12) LSB x 3.9 mg/LSB over sqrt(1600 Hz), one-sided
    expected = math.sqrt(3.2**2 + 1 / 12) * 3.9e3 / math.sqrt(1600)
    assert recording["samples"] == 20000 and recording["nsd_ug_rthz"] == pytest.approx(
        expected, rel=0.03
    )


def test_validate_noise_configured_terms_follow_the_profile_and_axis(monkeypatch, capsys, tmp_path):
    toml = tmp_path / "mine.toml"
    toml.write_text(
        'name = "mine"\nsampling_rate_hz = 3200\nfull_scale_g = 16\nadc_bits = 13\n'
        "noise_density_ug_rthz = 290\nmech_cutoff_hz = 7000\nanalog_cutoff_hz = 1600\n"
        "per_axis = { z = { noise_density_ug_rthz = 430 } }\n"
        '[[stages]]\nname = "gauss-markov"\nparams = { sigma_ug = 300, tau_s = 2 }\n'
    )
    base = ["--sensor-file", str(toml), "validate-noise", "--sensor", "mine", "--json"]
    code, stdout, _ = run(monkeypatch, capsys, *base, "--axis", "z")
    configured = json.loads(stdout)["allan"]["configured"]
    assert code == 0 and configured["nsd_ug_rthz"] == pytest.approx(430.0)
    assert configured["bias_instability_ug"] == pytest.approx(300 * 0.618 / 0.664, rel=0.01)
    assert any(t.startswith("gauss-markov.0") for t in configured["terms"])
    code, _, err = run(monkeypatch, capsys, *base, "--axis", "w")
    assert code == 2 and "--axis 'w'" in err and "Traceback" not in err
