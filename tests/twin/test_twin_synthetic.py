"""The check and the fit on a synthetic pair whose truth is known.

The device is built from the reference by a known chain: adxl345 with a 5 %
sensitivity error (the ``scale`` stage), 150 ug/sqrt(Hz) of noise, clocked at
3100 Hz (3.1 % below its nominal 3200 Hz), rotated by a known 3x3 rotation
(2 deg about z, 1 deg about x) and delayed by 2.37 samples. The expected
errors are computed here from those numbers, not by the code under test.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from sdt_framework.api import degrade
from sdt_framework.twin import Pair, Signal, check_twin, fit_twin
from sdt_framework.twin.align import at_rate

FS_REF = 20_000.0
RATE = 3100.0
GAIN_PCT = 5.0
NSD = 150.0
DELAY = 2.37 / RATE
TONES = {0: (80, 160, 315, 630), 1: (125, 400), 2: (250, 500)}  # axis -> Hz, 1 g each
TRUE_ROTATION = Rotation.from_euler("zx", [2.0, 1.0], degrees=True).as_matrix()


@pytest.fixture(scope="module")
def truth(registry):
    base = registry.sensor("adxl345")
    true = registry.bind(base.model_validate(  # the chain takes bound stages only
        {**base.content_dict(), "name": "adxl345-true", "noise_density_ug_rthz": NSD,
         "stages": [{"name": "scale", "params": {"error_pct": GAIN_PCT}}]}
    ))  # fmt: skip
    t = np.arange(int(8 * FS_REF)) / FS_REF
    rng = np.random.default_rng(3)
    reference = 1e-6 * rng.normal(size=(3, t.size))  # a quiet piezo: 1 ug per sample
    for axis, tones in TONES.items():
        for f in tones:
            reference[axis] += np.sin(2 * np.pi * f * t + axis)
    clocked = at_rate(true, RATE)
    twin = np.stack([degrade(row, FS_REF, clocked, seed=7, first_index=i)[0]
                     for i, row in enumerate(reference)])  # fmt: skip
    device = TRUE_ROTATION @ twin
    pair = Pair(
        "synthetic.IDE",
        Signal("channel 8", "piezo", ("x", "y", "z"), reference, FS_REF, 0.0),
        Signal("channel 32", "ADXL345", ("x", "y", "z"), device, RATE, DELAY),
        "000000000000",
    )
    return base, true, pair


def test_alignment_recovers_clock_delay_and_rotation(truth):
    base, _, pair = truth
    result = check_twin(pair, base)
    a = result.alignment
    assert a.clock_error_pct == pytest.approx(100 * (RATE / 3200 - 1), abs=1e-9)
    assert a.delay_s * RATE == pytest.approx(2.37, abs=0.05)  # sub-sample
    assert np.allclose(np.array(a.rotation), TRUE_ROTATION, atol=2e-3)


def _signal_bands(result) -> list[dict]:
    """Judgeable bands whose device RMS is 100x the noise of either chain there (290 ug/sqrt(Hz),
    the base's, x sqrt(B)): the tones' own bands. There the twin's error is the chain's;
    in weaker bands two noise draws, or the few mg a rotation moves between axes, are
    compared."""
    return [
        b for b in result.bands
        if b.judgeable
        and b.real_rms_g > 100 * 290e-6 * np.sqrt(b.f_upper_hz - b.f_lower_hz)
    ]  # fmt: skip


def test_the_true_profile_scores_zero_and_a_wrong_one_its_gain(truth):
    base, true, pair = truth
    right = _signal_bands(check_twin(pair, true))
    assert len(right) >= 8  # every tone's band
    assert max(abs(b.error_db) for b in right) < 0.05
    # the base profile lacks the 5 % gain: its twin is 20 log10(1/1.05) dB low in every band
    expected = 20 * np.log10(1 / (1 + GAIN_PCT / 100))
    wrong = _signal_bands(check_twin(pair, base))
    assert len(wrong) == len(right)
    for band in wrong:
        assert band.error_db == pytest.approx(expected, abs=0.05), band


def test_fit_recovers_gain_rate_and_noise(truth):
    base, _, pair = truth
    result = fit_twin(pair, base)
    fitted = result.fitted
    assert fitted["sampling_rate_hz"]["value"] == pytest.approx(RATE)
    gain = fitted["scale_error_pct"]
    assert gain["value"] == pytest.approx(GAIN_PCT, abs=0.2)
    # the device floor is the part's noise plus its quantisation (D^2/12 over Nyquist),
    # which the fit removes: what is left is the NSD the device was made with
    for axis in "xyz":
        assert fitted[f"noise_density_ug_rthz[{axis}]"]["value"] == pytest.approx(NSD, rel=0.06)
    assert result.profile["sampling_rate_hz"] == pytest.approx(RATE)
    assert result.profile["digital_cutoff_hz"] == pytest.approx(1599 * RATE / 3200, rel=1e-6)
    assert result.profile["stages"] == [
        {"name": "scale", "params": {"error_pct": round(gain["value"], 3)}}
    ]
    assert "mech_cutoff_hz" in result.kept and "alignment" in result.kept


def test_a_reference_without_motion_has_no_band_to_judge(registry):
    from sdt_framework.errors import SDTError

    rng = np.random.default_rng(0)
    quiet = 1e-4 * rng.normal(size=(1, int(4 * FS_REF)))  # white noise: the floor only
    device = 1e-4 * rng.normal(size=(1, int(4 * RATE)))
    pair = Pair(
        "rest.IDE",
        Signal("channel 8", "piezo", ("x",), quiet, FS_REF, 0.0),
        Signal("channel 32", "ADXL345", ("x",), device, RATE, 0.0),
        "000000000000",
    )
    with pytest.raises(SDTError, match="no band can be judged"):
        check_twin(pair, registry.sensor("adxl345"))
