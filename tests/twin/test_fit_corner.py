"""The anti-alias corner, fitted from a synthetic pair whose truth is known.

The device is the reference through the ADXL345 chain with its analog corner
moved from the datasheet's 1600 Hz to 900 Hz and a +3 % sensitivity error;
tones of 1 g on x from 100 Hz to 1.25 kHz reach well past half the corner,
where a first-order filter bends. ``fit`` from the datasheet profile must
find both; a pair whose tones stop far below the corner must not pretend to.
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.twin import Pair, Signal, check_twin, fit_twin

FS_REF = 20_000.0
RATE = 3200.0
TRUE_CORNER = 900.0
GAIN_PCT = 3.0


def _pair(true, tones: tuple[float, ...]) -> Pair:
    t = np.arange(int(6 * FS_REF)) / FS_REF
    reference = 1e-6 * np.random.default_rng(2).normal(size=(1, t.size))
    reference[0] += sum(np.sin(2 * np.pi * f * t) for f in tones)
    device = degrade(reference[0], FS_REF, true, seed=9)[0][None, :]
    return Pair("corner.IDE", Signal("ref", "piezo", ("x",), reference, FS_REF, 0.0),
                Signal("dev", "ADXL345", ("x",), device, RATE, 0.0), "000000000000")  # fmt: skip


@pytest.fixture(scope="module")
def specs(registry):
    base = registry.sensor("adxl345")
    true = base.model_validate(
        {**base.content_dict(), "name": "adxl345-true", "analog_cutoff_hz": TRUE_CORNER,
         "stages": [{"name": "scale", "params": {"error_pct": GAIN_PCT}}]}
    )  # fmt: skip
    return base, true


def test_fit_finds_the_corner_and_the_gain_together(specs):
    base, true = specs
    pair = _pair(true, (100.0, 200.0, 400.0, 630.0, 800.0, 1000.0, 1250.0))
    result = fit_twin(pair, base)
    corner = result.fitted["analog_cutoff_hz"]
    assert corner["value"] == pytest.approx(TRUE_CORNER, rel=0.05)
    assert abs(corner["value"] - TRUE_CORNER) < 4 * corner["uncertainty"] + 1.0
    assert result.fitted["scale_error_pct"]["value"] == pytest.approx(GAIN_PCT, abs=0.5)
    assert result.profile["analog_cutoff_hz"] == pytest.approx(corner["value"], abs=0.1)
    # the first-order corner's own shape: at 1.25 kHz the datasheet twin is too loud by
    # |H_900(1250)| / |H_1600(1250)| times the gain, in dB
    h = lambda fc: 1 / np.sqrt(1 + (1250.0 / fc) ** 2)  # noqa: E731
    expected = 20 * np.log10(h(1600.0) / h(TRUE_CORNER) / (1 + GAIN_PCT / 100))
    band = next(b for b in check_twin(pair, base).bands if b.f_lower_hz < 1250 < b.f_upper_hz)
    assert band.error_db == pytest.approx(expected, abs=0.1)


def test_tones_far_below_the_corner_determine_nothing(specs):
    base, true = specs
    result = fit_twin(_pair(true, (80.0, 160.0, 315.0)), base)
    assert "analog_cutoff_hz" not in result.fitted
    assert "shapes nothing" in result.kept["analog_cutoff_hz"]
