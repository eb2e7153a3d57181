"""Profiles whose stages do not bind: one line when asked for, left out (and named) in listings."""

from __future__ import annotations

import pytest
from sdt_plugins.sensors.adxl345 import ADXL345

from sdt_framework import SDTError, UnknownNameError, build_registry
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.bench.plan import plan_benchmark


def profile(name: str, **update):
    return ADXL345.model_validate({**ADXL345.model_dump(), "name": name, **update})


def test_a_profile_with_an_unknown_stage_is_left_out_of_the_listing_and_named():
    registry = build_registry()
    registry.add(profile("bad-stage", stages=[{"name": "cross-axes"}]))
    names = [s.name for s in registry.sensors()]
    assert "adxl345" in names and "bad-stage" not in names
    [line] = [p for p in registry.problems() if "bad-stage" in p]
    assert "left out" in line and "unknown stage 'cross-axes'" in line and "'cross-axis'" in line
    with pytest.raises(UnknownNameError, match="unknown stage 'cross-axes'"):
        registry.sensor("bad-stage")


def test_a_tolerance_on_an_unknown_stage_is_refused_when_units_are_drawn(tmp_path):
    """The nominal profile does not use the stage; a benchmark drawing units names it."""
    registry = build_registry()
    registry.add(profile("bad-tol", tolerances={"ofset.offset_mg": {"spread": 1}}))
    assert registry.sensor("bad-tol").name == "bad-tol"
    config = BenchmarkConfig(sensors=["bad-tol"], units=2, machines=["Motor-2"], report=False)
    with pytest.raises(UnknownNameError) as err:
        plan_benchmark(config, registry)
    message = str(err.value)
    assert "\n" not in message and "unknown stage 'ofset'" in message and "'offset'" in message


def test_a_tolerance_on_a_parameter_the_stage_lacks_lists_its_numeric_parameters():
    registry = build_registry()
    registry.add(profile("bad-param", tolerances={"offset.offset_g": {"spread": 1}}))
    with pytest.raises(SDTError) as err:
        registry.sensor("bad-param")
    assert str(err.value) == (
        "sensor 'bad-param': tolerance 'offset.offset_g' names no numeric parameter of "
        "stage 'offset'; its numeric parameters: offset_mg, tempco_mg_per_c"
    )


def test_a_valid_stage_tolerance_binds():
    registry = build_registry()
    registry.add(profile("ok-tol", tolerances={"scale.error_pct": {"spread": 2}}))
    assert registry.sensor("ok-tol").tolerances["scale.error_pct"].spread == 2
