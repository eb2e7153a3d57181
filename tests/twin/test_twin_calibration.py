"""What a pair can tell about itself: whose calibration is off, and whether a floor is judgeable.

A synthetic device made from the reference by the true ADXL345 chain (a 2 %
scale error, 150 ug/sqrt(Hz)), resting with gravity (1 g) on z. The reference
is then mis-calibrated by a known factor, or given a floor of its own; what
``check`` and ``fit`` must say follows from those numbers alone.
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.twin import Pair, Signal, check_twin, fit_twin
from sdt_framework.twin.align import at_rate
from sdt_framework.twin.check import MARGIN_DB

FS_REF = 20_000.0
RATE = 3200.0
NSD = 150.0  # ug/sqrt(Hz), the device's
TONES = (80.0, 160.0, 315.0, 630.0)  # Hz, 1 g each, on x


def _pair(true, reference_gain: float = 1.0, reference_nsd_ug: float = 0.01) -> Pair:
    """Device from the true reference; the recorded reference is ``reference_gain`` x it plus
    white noise of ``reference_nsd_ug`` ug/sqrt(Hz)."""
    t = np.arange(int(6 * FS_REF)) / FS_REF
    motion = np.zeros((3, t.size))
    motion[0] = sum(np.sin(2 * np.pi * f * t) for f in TONES)
    clocked = at_rate(true, RATE)
    device = np.stack([degrade(row, FS_REF, clocked, seed=5, first_index=i)[0]
                       for i, row in enumerate(motion)])  # fmt: skip
    device[2] += 1.0  # gravity on z: a DC-coupled part at rest on its mount reads it
    rng = np.random.default_rng(11)
    sigma = reference_nsd_ug * 1e-6 * np.sqrt(FS_REF / 2)  # white noise of that density
    reference = reference_gain * motion + sigma * rng.normal(size=motion.shape)
    return Pair(
        "calibration.IDE",
        Signal("channel 8", "piezo", ("x", "y", "z"), reference, FS_REF, 0.0),
        Signal("channel 32", "ADXL345", ("x", "y", "z"), device, RATE, 0.0),
        "000000000000",
    )


@pytest.fixture(scope="module")
def true(registry):
    base = registry.sensor("adxl345")
    return registry.bind(base.model_validate(  # the chain takes bound stages only
        {**base.content_dict(), "name": "adxl345-true", "noise_density_ug_rthz": NSD,
         "stages": [{"name": "scale", "params": {"error_pct": 2.0}}]}
    ))  # fmt: skip


def test_a_sound_reference_agrees_in_gain(true):
    k = check_twin(_pair(true), true).calibration
    assert k.static_g == pytest.approx(1.0, abs=0.01)
    assert k.tone_gain == pytest.approx(1.0, abs=0.01)
    assert not k.reference_off


def test_a_reference_reading_low_is_named_and_not_fitted_into_the_part(true, registry):
    # the reference reads 1/1.6 of the motion: the device, which reads gravity as 1 g,
    # then reads 1.6 x the twin at the tone, and the fault is the reference's
    pair = _pair(true, reference_gain=1 / 1.6)
    k = check_twin(pair, true).calibration
    assert k.static_g == pytest.approx(1.0, abs=0.01)
    assert k.tone_gain == pytest.approx(1.6, rel=0.01)
    assert k.reference_off
    fitted = fit_twin(pair, registry.sensor("adxl345"))
    assert "scale_error_pct" not in fitted.fitted
    assert "reference's calibration" in fitted.kept["scale"]


def test_a_device_without_gravity_is_not_taken_for_a_sound_one(true, registry):
    pair = _pair(true, reference_gain=1 / 1.6)
    device = pair.device.values.copy()
    device[2] -= 1.0  # an AC-coupled part: no static reading
    moved = Pair(pair.path, pair.reference,
                 Signal(pair.device.label, pair.device.part, pair.device.axes, device, RATE, 0.0),
                 pair.digest)  # fmt: skip
    k = check_twin(moved, true).calibration
    assert k.static_g < 0.05 and not k.reference_off
    # the fit cannot tell whose calibration is off, and fits the gain into the part
    fitted = fit_twin(moved, registry.sensor("adxl345"))
    assert fitted.fitted["scale_error_pct"]["value"] == pytest.approx(100 * (1.6 * 1.02 - 1), abs=1)


@pytest.mark.parametrize("reference_nsd_ug", [10.0, 100.0])
def test_a_floor_is_judged_only_below_a_quiet_reference(true, reference_nsd_ug):
    floors = check_twin(_pair(true, reference_nsd_ug=reference_nsd_ug), true).floors
    # the device's floor is its 150 ug/sqrt(Hz) plus quantisation (step^2/12 spread over
    # Nyquist): judgeable only with the reference's floor 10 dB below it
    step = true.quantisation_step_g
    device = np.hypot(NSD, 1e6 * step / np.sqrt(12) / np.sqrt(RATE / 2))
    expected = 20 * np.log10(device / reference_nsd_ug) >= MARGIN_DB
    for floor in floors:
        assert floor.device_ug == pytest.approx(device, rel=0.1)
        assert floor.reference_ug == pytest.approx(reference_nsd_ug, rel=0.1)
        assert floor.judgeable == expected, floor
