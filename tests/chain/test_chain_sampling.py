"""ADC sampling: numpy-interp semantics, output length, aliasing amplitude."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.chain import RunContext, Sample, design_lowpass, lowpass_gain
from sdt_framework.chain.stages import sample_count
from sdt_framework.specs import SensorSpec


@pytest.mark.parametrize(
    ("n", "fs_in", "fs_out", "m"),
    [
        (240000, 20000, 3200, 38400),
        (240000, 20000, 4000, 48000),
        (7, 20000, 3200, 1),
        (8, 20000, 3200, 2),
        (102395, 20000, 3200, 16384),
        (11, 10, 5, 6),
    ],
)
def test_sample_count_is_floor_formula(n: int, fs_in: float, fs_out: float, m: int) -> None:
    assert sample_count(n, fs_in, fs_out) == m


@pytest.mark.parametrize(("fs_in", "fs_out"), [(20000, 3200), (20000, 4000), (48000, 4410)])
def test_sampling_is_bit_identical_to_numpy_interp(fs_in: float, fs_out: float) -> None:
    x = np.random.default_rng(1).standard_normal((3, 5001))
    y = Sample(fs_in, fs_out).apply(x, RunContext())
    t_in = np.arange(x.shape[1]) / fs_in
    t_out = np.arange(sample_count(x.shape[1], fs_in, fs_out)) / fs_out
    for row, out in zip(x, y, strict=True):
        np.testing.assert_array_equal(out, np.interp(t_out, t_in, row))


def test_tone_above_nyquist_aliases_with_the_analog_filters_gain(adxl345: SensorSpec) -> None:
    """A 2500 Hz tone into the ADXL345 chain appears at |2500 - 3200| = 700 Hz.

    Expected amplitude: |H_mech H_ana|(2500 Hz) at 20 kHz, times the linear
    interpolation's gain for that tone (position fractions cycle through
    0, 1/4, 1/2, 3/4 since 20000/3200 = 6.25; the mean of
    e^{-jwd}((1-d) + d e^{jw}) over them), times |H_dig|(700 Hz) at 3200 Hz.
    """
    f0, fs, amplitude = 2500.0, 20000.0, 1.0
    x = amplitude * np.sin(2 * np.pi * f0 * np.arange(200000) / fs)
    y, fs_out = degrade(x, fs, adxl345, noise=False)
    analog = (
        lowpass_gain(design_lowpass(2, 7000, fs), [f0], fs)
        * lowpass_gain(design_lowpass(1, 1600, fs), [f0], fs)
    )[0]
    w = 2 * np.pi * f0 / fs
    d = np.array([0, 0.25, 0.5, 0.75])
    interp = abs(np.mean(np.exp(-1j * w * d) * ((1 - d) + d * np.exp(1j * w))))
    digital = lowpass_gain(design_lowpass(1, 1599, fs_out), [700.0], fs_out)[0]
    tail = y[-3200:]  # last second, steady state, 1 Hz bins
    spectrum = 2 * np.abs(np.fft.rfft(tail)) / tail.size
    assert np.argmax(spectrum) == 700
    assert spectrum[700] == pytest.approx(amplitude * analog * interp * digital, rel=2e-3)
    assert spectrum[700] < 0.7 * amplitude  # really attenuated, not just passed
