"""Parts in the registry: resolution by name, one namespace with sensors, conformance."""

from __future__ import annotations

import types

import pytest

import sdt_framework.registry
from sdt_framework import SensorSpec, build_registry, hookimpl
from sdt_framework.conformance import ConformanceError, check_plugin, check_spec
from sdt_framework.errors import DuplicateNameError, SDTError, UnknownNameError


def plugin(hook: str, *specs) -> types.ModuleType:
    module = types.ModuleType(f"plugin_{hook}")

    def impl(register):
        for spec in specs:
            register(spec)

    setattr(module, hook, hookimpl(impl))
    return module


def sensor(name: str) -> SensorSpec:
    return SensorSpec(
        name=name,
        sampling_rate_hz=100,
        full_scale_g=2,
        adc_bits=8,
        noise_density_ug_rthz=1,
        mech_cutoff_hz=40,
        analog_cutoff_hz=30,
    )


def test_a_part_resolves_by_name_with_or_without_a_mode(toy):
    registry = build_registry(entry_points=False, plugins=[plugin("register_parts", toy)])
    assert registry.sensor("toy").name == "toy[odr=4000,range=2g]"
    assert registry.sensor("toy[range=8g]").full_scale_g == 8
    assert registry.sensor("toy[odr=4000,range=8g]") == registry.sensor("toy[range=8g]")
    assert registry.sensors() == []  # parts are listed by parts(), not as profiles
    assert [p.name for p in registry.parts()] == ["toy"]


def test_unknown_names_list_sensors_and_parts(toy):
    registry = build_registry(
        entry_points=False,
        plugins=[plugin("register_parts", toy), plugin("register_sensors", sensor("plain"))],
    )
    with pytest.raises(UnknownNameError, match=r"unknown sensor 'tyo'.*Did you mean 'toy'"):
        registry.sensor("tyo")
    with pytest.raises(UnknownNameError, match="unknown part 'plain'"):
        registry.sensor("plain[range=2g]")  # a profile has no modes
    with pytest.raises(SDTError, match="range=3g is not an option"):
        registry.sensor("toy[range=3g]")


def test_a_part_and_a_sensor_may_not_share_a_name(toy):
    registry = build_registry(
        entry_points=False,
        plugins=[plugin("register_sensors", sensor("toy")), plugin("register_parts", toy)],
    )
    assert registry.plugins()[-1].status == "conflict"
    with pytest.raises(DuplicateNameError, match="part 'toy' is registered twice"):
        registry.check()


def test_brackets_are_reserved_for_modes():
    registry = build_registry(
        entry_points=False, plugins=[plugin("register_sensors", sensor("x[range=2g]"))]
    )
    assert "brackets are reserved for part modes" in registry.plugins()[-1].error


@pytest.mark.catalog
def test_the_catalogue_passes_the_conformance_checks():
    import sdt_sensors_catalog as catalogue

    specs = check_plugin(catalogue)
    assert len(specs) >= 12


@pytest.mark.catalog
def test_conformance_turns_error_terms_on_and_needs_their_stages(monkeypatch):
    """A part whose error terms need stages nobody installed fails the check, naming the stage."""
    part = build_registry().part("adxl355")
    check_spec(part)  # with the built-in stages: passes
    blocked = build_registry(environ={"SDT_BLOCK_PLUGINS": "stages-errors"})
    monkeypatch.setattr(sdt_framework.registry, "default_registry", lambda: blocked)
    with pytest.raises(ConformanceError, match="unknown stage 'offset'"):
        check_spec(part)
