"""Profiles for the chain tests: the built-in plugins' own, whatever else is installed."""

from __future__ import annotations

import pytest
from sdt_plugins.sensors import adxl345, adxl357, wilcoxon_786b10

from sdt_framework import build_registry
from sdt_framework.specs import SensorSpec

#: the built-in profiles of paper Table 1, as their plugins register them (not copies that
#: could drift), from a registry of those plugins alone (no entry points, no SDT_* switches)
_BUILTIN = build_registry(entry_points=False, plugins=[adxl345, adxl357, wilcoxon_786b10])
ADXL345 = _BUILTIN.sensor("adxl345")
ADXL357 = _BUILTIN.sensor("adxl357")
REFERENCE = _BUILTIN.sensor("wilcoxon-786b10")


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
