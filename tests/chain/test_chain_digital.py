"""Noise injection, saturation and quantisation stages on their own."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.chain import Quantise, RunContext, WhiteNoise
from sdt_framework.specs import SensorSpec


def test_quantisation_step_is_two_gmax_over_two_to_the_bits() -> None:
    stage = Quantise(3200, full_scale_g=16, bits=13)
    step = 32 / 8192
    x = np.random.default_rng(2).uniform(-15, 15, (2, 50000))
    y = stage.apply(x, RunContext())
    levels = y / step
    np.testing.assert_allclose(levels, np.round(levels), atol=1e-9)
    assert np.max(np.abs(y - x)) <= step / 2 + 1e-12
    assert np.unique(np.diff(np.unique(np.round(levels)))).tolist() == [1.0]


def test_saturation_clips_at_full_scale() -> None:
    stage = Quantise(3200, full_scale_g=16, bits=13)
    y = stage.apply(np.array([[-100.0, -16.0001, 16.0001, 250.0, 3.0]]), RunContext())
    assert y[0, :4].tolist() == [-16.0, -16.0, 16.0, 16.0]
    assert y[0, 4] == pytest.approx(3.0, abs=32 / 8192 / 2)


def test_injected_noise_has_the_datasheet_sigma() -> None:
    stage = WhiteNoise(3200, nsd_ug_rthz=290)
    expected = 290e-6 * np.sqrt(1600)  # 11.6 mg
    assert stage.sigma_g == pytest.approx(expected, rel=1e-12)
    y = stage.apply(np.zeros((4, 50000)), RunContext(seed=3, acquisition_ids=(0, 1, 2, 3)))
    # sample SD of 200000 Gaussian values: relative standard error 0.16 %
    assert np.std(y) == pytest.approx(expected, rel=0.01)
    assert abs(np.mean(y)) < 5 * expected / np.sqrt(y.size)
    # white: lag-1 autocorrelation near zero
    r1 = np.mean(y[:, 1:] * y[:, :-1]) / np.var(y)
    assert abs(r1) < 0.01
    assert not np.array_equal(y[0], y[1])  # each acquisition has its own draw


def test_noise_switch_and_profile_flag(adxl345: SensorSpec) -> None:
    x = np.zeros(20000)
    quiet, _ = degrade(x, 20000, adxl345, noise=False)
    assert np.all(quiet == 0.0)
    silent = adxl345.model_copy(update={"inject_noise": False})
    y, _ = degrade(x, 20000, silent, seed=5)
    assert np.all(y == 0.0)
    noisy, _ = degrade(x, 20000, adxl345, seed=5)
    assert np.std(noisy) > 0.005


def test_requantise_false_skips_saturation_and_rounding(adxl345: SensorSpec) -> None:
    raw = adxl345.model_copy(update={"requantise": False})
    x = np.full(2000, 40.0)  # far beyond 16 g
    y, _ = degrade(x, 20000, raw, noise=False)
    assert y.max() > 16.0
    step = adxl345.quantisation_step_g
    assert not np.allclose(y / step, np.round(y / step))
