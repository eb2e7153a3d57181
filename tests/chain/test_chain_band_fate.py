"""band_fate: the chain says whether a band reaches the output passed, attenuated or aliased.

The expected fold is |f - k F_target| and the expected level a tone's, measured
through ``degrade``; the gains come from scipy's Butterworth designs here.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.signal import butter, sosfreqz

from sdt_framework.api import degrade
from sdt_framework.chain import band_fate
from sdt_framework.specs import SensorSpec

FS = 20000.0


def _db(order: int, cutoff: float, f: float, fs: float) -> float:
    _, h = sosfreqz(butter(order, cutoff, fs=fs, output="sos"), worN=[f], fs=fs)
    return float(20 * np.log10(abs(h[0])))


def _decimating(sensor: SensorSpec) -> SensorSpec:
    return sensor.model_copy(update={"name": f"{sensor.name}-dec", "sampling": "decimate"})


def test_the_paper_adxl357_shows_a_3_6_khz_resonance_aliased_to_400_hz(adxl357) -> None:
    fate = band_fate(adxl357, FS, (3500.0, 3700.0))
    assert fate.kind == "aliased"
    assert fate.folded_hz == pytest.approx((300.0, 500.0), abs=0.5)  # |f - 4000|
    # the line that lands nearest the output band's bottom: 3700 Hz -> 300 Hz
    expected = _db(2, 5500, 3500, FS) + _db(1, 1500, 3500, FS) + _db(8, 1000, 500, 4000)
    assert fate.gain_db == pytest.approx(expected, abs=0.05)
    assert "aliased" in fate.describe() and "300-500 Hz" in fate.describe()


def test_a_decimating_adxl357_shows_the_same_band_attenuated(adxl357) -> None:
    fate = band_fate(_decimating(adxl357), FS, (3500.0, 3700.0))
    assert fate.kind == "attenuated"
    assert fate.folded_hz is None
    expected = _db(2, 5500, 3500, FS) + _db(1, 1500, 3500, FS) + _db(8, 1000, 3500, FS)
    assert fate.gain_db == pytest.approx(expected, abs=0.05)
    assert fate.gain_db < -90


@pytest.mark.parametrize("decimate", [False, True])
def test_the_gain_it_reports_is_what_a_tone_measures(adxl357, decimate: bool) -> None:
    sensor = _decimating(adxl357) if decimate else adxl357
    f0 = 2600.0  # folds to 1400 Hz
    x = np.sin(2 * np.pi * f0 * np.arange(int(6 * FS)) / FS)
    y, fs_out = degrade(x, FS, sensor, noise=False)
    tail = y[-int(2 * fs_out) :]
    line = 2 * np.abs(np.fft.rfft(tail))[2 * 1400] / tail.size
    fate = band_fate(sensor, FS, (f0 - 1e-6, f0 + 1e-6), points=2)
    # interpolation (0.97 at 2.6 kHz from 20 kHz) and quantisation left out of band_fate
    assert 20 * np.log10(max(line, 1e-9)) == pytest.approx(
        fate.gain_db, abs=0.5 if not decimate else 1
    )


def test_a_band_in_the_passband_is_passed_and_one_above_the_corner_attenuated(adxl357) -> None:
    assert band_fate(adxl357, FS, (125.0, 500.0)).kind == "passed"
    assert band_fate(_decimating(adxl357), FS, (125.0, 500.0)).kind == "passed"
    high = band_fate(adxl357, FS, (1600.0, 1900.0))  # below the Nyquist, past the 1 kHz corner
    assert high.kind == "attenuated" and high.folded_hz is None


def test_a_sar_part_aliases_and_a_native_reference_passes(adxl345, reference) -> None:
    assert band_fate(adxl345, FS, (2900.0, 5000.0)).kind == "aliased"
    assert band_fate(reference, FS, (2900.0, 5000.0)).kind == "passed"


def test_a_band_beyond_the_recording_is_refused(adxl357) -> None:
    with pytest.raises(ValueError, match="Nyquist frequency of the 20000 Hz recording"):
        band_fate(adxl357, FS, (3000.0, 12000.0))
