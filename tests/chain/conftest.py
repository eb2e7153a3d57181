"""Profiles for the chain tests, built here so tests never depend on what is installed."""

from __future__ import annotations

import pytest

from sdt_framework.specs import SensorSpec

ADXL345 = SensorSpec(
    name="adxl345",
    sampling_rate_hz=3200,
    full_scale_g=16,
    adc_bits=13,
    noise_density_ug_rthz=290,
    mech_cutoff_hz=7000,
    mech_order=2,
    analog_cutoff_hz=1600,
    analog_order=1,
    digital_cutoff_hz=1599,
    digital_order=1,
)
ADXL357 = SensorSpec(
    name="adxl357",
    sampling_rate_hz=4000,
    full_scale_g=40,
    adc_bits=20,
    noise_density_ug_rthz=90,
    mech_cutoff_hz=5500,
    mech_order=2,
    analog_cutoff_hz=1500,
    analog_order=1,
    digital_cutoff_hz=1000,
    digital_order=8,
)
REFERENCE = SensorSpec(
    name="wilcoxon-786b10",
    sampling_rate_hz=20000,
    full_scale_g=80,
    adc_bits=24,
    noise_density_ug_rthz=5,
    inject_noise=False,
    requantise=False,
    mech_cutoff_hz=30000,
    mech_order=2,
    analog_cutoff_hz=10000,
    analog_order=1,
)


@pytest.fixture
def adxl345() -> SensorSpec:
    """The ADXL345 profile of paper Table 1."""
    return ADXL345


@pytest.fixture
def adxl357() -> SensorSpec:
    """The ADXL357 profile of paper Table 1."""
    return ADXL357


@pytest.fixture
def reference() -> SensorSpec:
    """The reference Wilcoxon chain of paper Table 1."""
    return REFERENCE


@pytest.fixture(params=[ADXL345, ADXL357], ids=lambda s: s.name)
def mems(request: pytest.FixtureRequest) -> SensorSpec:
    """Each MEMS profile of paper Table 1."""
    return request.param
