"""The rate-following reference and the rule for what a recording can simulate."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework import SensorSpec, build_registry
from sdt_framework.api import degrade
from sdt_framework.chain import build_stages, simulation_problem

MEMS = dict(
    name="mems",
    sampling_rate_hz=3200,
    full_scale_g=16,
    adc_bits=13,
    noise_density_ug_rthz=290,
    mech_cutoff_hz=7000,
    analog_cutoff_hz=1600,
)


@pytest.fixture(scope="module")
def native() -> SensorSpec:
    return build_registry().sensor("native-reference")


@pytest.mark.parametrize("fs", [12000.0, 25600.0, 51200.0, 20000.0])
def test_native_reference_is_the_identity_at_any_rate(native, fs):
    x = np.random.default_rng(3).normal(size=(2, 4000)) * 5.0
    y, rate = degrade(x, fs, native, seed=9)
    assert rate == fs
    assert np.array_equal(y, x)  # bit for bit: no filter, no noise, no requantisation
    assert build_stages(native, fs) == ()
    assert simulation_problem(native, fs) is None


def test_a_missing_cutoff_leaves_its_stage_out():
    spec = SensorSpec(**{**MEMS, "mech_cutoff_hz": None})
    names = [s.name for s in build_stages(spec, 20000.0)]
    assert names == ["analog", "sample", "noise", "quantise"]


@pytest.mark.parametrize(
    ("changes", "fs", "reason"),
    [
        ({}, 20000.0, None),
        ({"sampling_rate_hz": 25600}, 20000.0, "samples at 25600 Hz, above the data's 20000 Hz"),
        ({}, 3000.0, "samples at 3200 Hz, above the data's 3000 Hz"),
        # resampled below 12 kHz with 7 kHz in band: the recording lacks 6-7 kHz to alias
        ({"analog_cutoff_hz": 8000}, 12000.0, "passes up to 7000 Hz to its sampler"),
        ({"analog_cutoff_hz": None, "mech_cutoff_hz": None}, 12000.0, "no mechanical or analog"),
        ({"sampling_rate_hz": 12000}, 12000.0, None),  # same rate: nothing resampled
    ],
)
def test_what_a_recording_can_simulate(changes, fs, reason):
    problem = simulation_problem(SensorSpec(**{**MEMS, **changes}), fs)
    if reason is None:
        assert problem is None
    else:
        assert reason in problem


def test_the_paper_profiles_are_simulable_from_20_and_12_khz():
    registry = build_registry()
    for name in ("adxl345", "adxl357"):
        for fs in (20000.0, 12000.0):
            assert simulation_problem(registry.sensor(name), fs) is None
    assert simulation_problem(registry.sensor("wilcoxon-786b10"), 20000.0) is None
    assert "above the data's 12000 Hz" in simulation_problem(
        registry.sensor("wilcoxon-786b10"), 12000.0
    )
