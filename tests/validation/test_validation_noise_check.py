"""Zero-motion noise check (paper section 3.1, Table 2)."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.chain import ChainInputError
from sdt_framework.specs import SensorSpec
from sdt_framework.validation import NoiseCheck, WindowStats, noise_check, window_stats
from sdt_framework.validation.noise_check import zero_motion_length


def test_adxl345_reproduces_table_2_within_1_and_2_percent(adxl345: SensorSpec) -> None:
    result = noise_check(adxl345, seed=0)
    data = result.to_dict()
    assert result.sdt_signal.size == 8 * 2048 and result.sdt_fs == 3200
    assert data["sdt"]["rms_mg"] == pytest.approx(11.67, rel=0.01)
    assert data["sdt"]["nsd_ug_rthz"] == pytest.approx(292.2, rel=0.02)
    lo, hi = data["sdt"]["rms_mg_ci95"]
    assert lo < data["sdt"]["rms_mg"] < hi


def test_zero_motion_length_is_the_smallest_input_giving_the_windows(
    adxl345: SensorSpec,
) -> None:
    n = zero_motion_length(adxl345, 20000, 16384)
    assert int((n - 1) * 3200 / 20000) + 1 == 16384
    assert int((n - 2) * 3200 / 20000) + 1 == 16383


def test_window_stats_against_known_signals() -> None:
    fs, n = 3200.0, 2048
    t = np.arange(4 * n) / fs
    # an offset is not noise: RMS is of the mean-removed window (amplitude / sqrt 2)
    tone = 0.5 + 0.02 * np.sin(2 * np.pi * 400 * t)
    assert window_stats(tone, fs, 4, n).rms_mg == pytest.approx(
        np.full(4, 20 / np.sqrt(2)), rel=1e-3
    )
    # white noise of SD sigma has a one-sided density sigma / sqrt(fs / 2)
    sigma = 0.01
    noise = sigma * np.random.default_rng(0).standard_normal(64 * n)
    nsd = window_stats(noise, fs, 64, n).nsd_ug_rthz
    assert nsd.mean() == pytest.approx(sigma / np.sqrt(fs / 2) * 1e6, rel=0.02)


def test_comparison_follows_table_2_definitions() -> None:
    spread = np.array([-1.0, 1.0] * 4)
    rec = WindowStats(12.77 + 0.1 * spread, 314.02 + spread)
    sdt = WindowStats(11.67 + 0.1 * spread, 292.20 + spread)
    check = NoiseCheck("s", 0, 8, 2048, 20000, 1, np.zeros(1), 3200, sdt, np.zeros(1), 3200, rec)
    cmp = check.comparison()
    assert cmp["relative_error_pct"]["nsd"] == pytest.approx(6.95, abs=0.005)  # paper's value
    assert cmp["relative_error_pct"]["rms"] == pytest.approx(100 * 1.10 / 12.77, rel=1e-9)
    assert cmp["p_value"]["nsd"] < 1e-6


def test_recording_of_the_same_noise_is_not_distinguished(adxl345: SensorSpec) -> None:
    step = adxl345.quantisation_step_g
    rec = step * np.round(np.random.default_rng(8).normal(0.03, 0.01165, 16384) / step)
    data = noise_check(adxl345, recording=rec).to_dict()
    assert data["recording"]["rms_mg"] == pytest.approx(11.65, rel=0.03)
    assert data["relative_error_pct"]["rms"] < 4
    assert data["p_value"]["rms"] > 1e-3
    assert set(data) >= {"sdt", "recording", "relative_error_pct", "p_value"}


def test_short_recording_is_an_error(adxl345: SensorSpec) -> None:
    with pytest.raises(ChainInputError, match=r"need one axis of >= 16384 samples"):
        noise_check(adxl345, recording=np.zeros(1000), label="short.csv")
