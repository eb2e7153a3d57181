"""The velocity overall and the envelope line amplitudes against analysis (issue 40, items 2, 9).

Expected values are computed here from the signal's construction: a sine of
known velocity r.m.s. (acceleration amplitude A g at f reads A G / (2 pi f) /
sqrt 2 m/s), white acceleration noise of known one-sided density S = 2
sigma^2 / fs g^2/Hz (velocity mean square over f1-f2: S G^2 (1/f1 - 1/f2) /
(4 pi^2)), and an amplitude-modulated carrier whose envelope line has a known
amplitude, placed half-way between two lines.
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.severity import envelope_spectrum, velocity_spectrum

G = 9.80665


@pytest.mark.parametrize("fs", [3200.0, 20000.0, 25600.0])
def test_the_overall_of_a_4_5_mm_s_sine_reads_4_5_mm_s_at_every_rate(fs: float) -> None:
    f0, v_rms = 31.7, 4.5  # between two 0.5 Hz lines; zone C/D edge of group 2 rigid
    amplitude_g = v_rms * 1e-3 * np.sqrt(2) * 2 * np.pi * f0 / G
    t = np.arange(int(10 * fs)) / fs
    spec = velocity_spectrum(amplitude_g * np.sin(2 * np.pi * f0 * t), fs)
    assert spec.overall == pytest.approx(v_rms, rel=2e-3)  # the sum of lines read 5.512
    assert spec.band_hz == (10.0, 1000.0) and spec.note == ""


def test_the_overall_of_white_noise_is_its_density_integrated_over_the_band() -> None:
    fs, sigma, seconds = 2500.0, 0.05, 600.0
    gen = np.random.default_rng(3)
    x = sigma * gen.standard_normal(int(seconds * fs))
    density = 2 * sigma**2 / fs  # g^2/Hz, one-sided
    # band edges half-way between the 0.5 Hz lines: the lines 10.5-999.5 Hz stand for it
    low, high = 10.25, 999.75
    expected = np.sqrt(density * G**2 * (1 / low - 1 / high) / (4 * np.pi**2)) * 1e3
    spec = velocity_spectrum(x, fs, band=(low, high))
    assert spec.overall == pytest.approx(expected, rel=0.02)


def test_a_band_above_the_chain_or_nyquist_is_clipped_and_says_so() -> None:
    fs = 1344.0
    t = np.arange(int(20 * fs)) / fs
    spec = velocity_spectrum(np.sin(2 * np.pi * 50 * t), fs, bandwidth_hz=149.3)
    assert spec.band_hz == (10.0, 149.3) and spec.freq.max() <= 149.3
    assert spec.note == "10-149.3 Hz, not 10-1000 Hz: the chain's bandwidth is 149.3 Hz"
    spec = velocity_spectrum(np.sin(2 * np.pi * 50 * t), fs)
    assert spec.band_hz == (10.0, 672.0) and "Nyquist frequency is 672 Hz" in spec.note


def test_a_2_hz_edge_needs_two_seconds_of_record() -> None:
    fs = 2560.0
    x = np.random.default_rng(0).standard_normal(int(0.64 * fs))
    with pytest.raises(SDTError, match="from 2 Hz needs segments of at least 2 s"):
        velocity_spectrum(x, fs, band=(2.0, 1000.0))
    long = np.random.default_rng(0).standard_normal(int(8 * fs))
    assert velocity_spectrum(long, fs, band=(2.0, 1000.0)).band_hz == (2.0, 1000.0)


@pytest.mark.parametrize("offset", [0.0, 0.25, 0.5])
def test_an_envelope_line_between_two_lines_reads_its_amplitude(offset: float) -> None:
    fs, seconds = 20000.0, 4.0
    t = np.arange(int(seconds * fs)) / fs
    f_mod = (300 + offset) / seconds  # 75 Hz plus a fraction of the 0.25 Hz spacing
    depth, carrier = 0.3, 3000.0
    x = (1 + depth * np.cos(2 * np.pi * f_mod * t)) * np.cos(2 * np.pi * carrier * t)
    spec = envelope_spectrum(x, fs, (2000.0, 4000.0))
    near = np.abs(spec.freq - f_mod) < 1.0
    # the envelope is 1 + 0.3 cos: its line reads 0.3 gE wherever it falls (Hann: 0.255)
    assert spec.values[near].max() == pytest.approx(depth, rel=5e-3)
    assert spec.unit == "gE" and spec.window == "flat-top"


@pytest.mark.parametrize(
    ("corners", "expected"),
    [
        # (mechanical, analog, digital) -3 dB corners at 3200 Hz: the lowest sets the band
        ((500.0, 1000.0, None), 500.0),  # a mechanical corner below the electrical ones
        ((None, 1000.0, 800.0), 800.0),
        ((5000.0, None, None), 1600.0),  # above the output Nyquist: Nyquist bounds it
    ],
)
def test_chain_bandwidth_is_the_lowest_corner_of_every_stage(adxl345, corners, expected):
    """The envelope band and the V_RMS band check read a chain's band from every stage the
    chain runs, the mechanical low-pass included (it was left out: an ISM330DHCX at 6667 Hz,
    mechanical corner 2600 Hz, read 3333.5 Hz)."""
    from sdt_framework.severity import chain_bandwidth

    mech, analog, digital = corners
    spec = adxl345.model_copy(
        update={"sampling_rate_hz": 3200.0, "mech_cutoff_hz": mech, "analog_cutoff_hz": analog,
                "digital_cutoff_hz": digital}
    )  # fmt: skip
    assert chain_bandwidth(spec) == expected
