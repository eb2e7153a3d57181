"""The registry: discovery, in-process plugins, and every error path with its message."""

from __future__ import annotations

import types

import pytest

from sdt_framework import (
    DuplicateNameError,
    SensorSpec,
    UnknownNameError,
    build_registry,
    hookimpl,
)

TABLE1 = {
    "wilcoxon-786b10": (20000, 80, 24, 5, 30000, 10000, None, None),
    "adxl345": (3200, 16, 13, 290, 7000, 1600, 1599, 1),
    "adxl357": (4000, 40, 20, 90, 5500, 1500, 1000, 8),
}

SENSOR_PLUGIN = """
from sdt_framework import SensorSpec, hookimpl

@hookimpl
def register_sensors(register):
    register(SensorSpec(name="{name}", sampling_rate_hz=1000, full_scale_g=2, adc_bits=10,
                        noise_density_ug_rthz=100, mech_cutoff_hz=3000, analog_cutoff_hz=400))
"""


def sensor_plugin(name: str) -> types.ModuleType:
    module = types.ModuleType(f"plugin_{name}")
    exec(SENSOR_PLUGIN.format(name=name), module.__dict__)
    return module


def test_builtins_have_the_paper_table1_values():
    registry = build_registry()
    for name, values in TABLE1.items():
        s = registry.sensor(name)
        got = (
            s.sampling_rate_hz,
            s.full_scale_g,
            s.adc_bits,
            s.noise_density_ug_rthz,
            s.mech_cutoff_hz,
            s.analog_cutoff_hz,
            s.digital_cutoff_hz,
            s.digital_order,
        )
        assert got == values
        assert s.mech_order == 2 and s.analog_order == 1
        assert s.distribution == "sdt-framework" and s.source
    assert registry.sensor("wilcoxon-786b10").inject_noise is False
    assert {c.name for c in registry.classifiers()} >= {"lr", "knn", "rf", "xgb", "mlp"}
    assert registry.feature_set("paper8").bytes_per_window == 32


def test_unknown_name_lists_available_and_closest_match():
    registry = build_registry()
    with pytest.raises(UnknownNameError) as info:
        registry.sensor("adxl34")
    message = str(info.value)
    assert "unknown sensor 'adxl34'" in message
    assert "Did you mean 'adxl345'?" in message
    assert "adxl357" in message and "wilcoxon-786b10" in message


def test_in_process_plugin_is_stamped_with_provenance():
    registry = build_registry(entry_points=False, plugins=[sensor_plugin("mine")])
    spec = registry.sensor("mine")
    assert spec.plugin == "plugin_mine" and spec.distribution == "(in-process)"


def test_add_accepts_a_dict_and_validates_it():
    registry = build_registry(entry_points=False)
    registry.add(
        {
            "name": "d",
            "sampling_rate_hz": 100,
            "full_scale_g": 2,
            "adc_bits": 8,
            "noise_density_ug_rthz": 1,
            "mech_cutoff_hz": 40,
            "analog_cutoff_hz": 30,
        },
        SensorSpec,
    )
    assert registry.sensor("d").adc_bits == 8


def test_duplicate_names_from_two_distributions_name_both(fake_dist):
    fake_dist("sdt-one", {"dup-a": "dup_a"}, {"dup_a": SENSOR_PLUGIN.format(name="twin")})
    fake_dist("sdt-two", {"dup-b": "dup_b"}, {"dup_b": SENSOR_PLUGIN.format(name="twin")})
    registry = build_registry()
    with pytest.raises(DuplicateNameError) as info:
        registry.sensor("twin")
    message = str(info.value)
    assert "sensor 'twin' is registered twice" in message
    assert "sdt-one" in message and "sdt-two" in message
    assert any("registered twice" in line for line in registry.problems())
    statuses = {p.name: p.status for p in registry.plugins()}
    assert statuses["dup-a"] == "loaded" and statuses["dup-b"] == "conflict"
    assert registry.sensor("adxl345").name == "adxl345"  # everything else still works


def test_plugin_failing_to_import_is_reported_and_others_keep_working(fake_dist):
    fake_dist(
        "sdt-broken", {"broken": "broken_mod"}, {"broken_mod": "raise RuntimeError('boom')\n"}
    )
    registry = build_registry()
    [info] = [p for p in registry.plugins() if p.name == "broken"]
    assert info.status == "error" and info.distribution == "sdt-broken"
    assert "RuntimeError: boom" in info.error
    assert "plugin 'broken' (sdt-broken)" in registry.problems()[0]
    assert registry.sensor("adxl345").name == "adxl345"  # the rest still loads


def test_hook_that_raises_marks_only_that_plugin(fake_dist):
    source = (
        "from sdt_framework import hookimpl\n@hookimpl\n"
        "def register_sensors(register):\n    raise ValueError('bad table')\n"
    )
    fake_dist("sdt-raiser", {"raiser": "raiser_mod"}, {"raiser_mod": source})
    registry = build_registry()
    [info] = [p for p in registry.plugins() if p.name == "raiser"]
    assert info.status == "error"
    assert info.error == "register_sensors raised ValueError: bad table"


def test_invalid_spec_from_a_plugin_names_the_plugin(fake_dist):
    source = (
        "from sdt_framework import hookimpl\n@hookimpl\ndef register_sensors(register):\n"
        "    register({'name': 'x', 'sampling_rate_hz': -1})\n"
    )
    fake_dist("sdt-invalid", {"invalid": "invalid_mod"}, {"invalid_mod": source})
    [info] = [p for p in build_registry().plugins() if p.name == "invalid"]
    assert info.status == "error" and "invalid sensor" in info.error
    assert "sampling_rate_hz" in info.error


def test_hook_with_unknown_argument_is_rejected():
    module = types.ModuleType("wrong_args")

    @hookimpl
    def register_sensors(register, extra):  # 'extra' is not in the hookspec
        pass

    module.register_sensors = register_sensors
    info = build_registry(entry_points=False).register_plugin(module)
    assert info.status == "error"
    assert "invalid hook implementation" in info.error and "extra" in info.error


def test_misspelled_hook_is_rejected():
    module = types.ModuleType("typo")

    @hookimpl
    def register_sensor(register):  # missing the final 's'
        pass

    module.register_sensor = register_sensor
    info = build_registry(entry_points=False).register_plugin(module)
    assert info.status == "error" and "register_sensor" in info.error


def test_only_and_block_switches(fake_dist):
    fake_dist(
        "sdt-extra",
        {"extra-sensor": "extra_mod"},
        {"extra_mod": SENSOR_PLUGIN.format(name="extra")},
    )
    blocked = build_registry(environ={"SDT_BLOCK_PLUGINS": "sdt-extra"})
    assert "extra" not in [s.name for s in blocked.sensors()]
    assert {p.name: p.status for p in blocked.plugins()}["extra-sensor"] == "blocked"
    only = build_registry(environ={"SDT_PLUGINS": "extra-sensor,adxl345"})
    assert [s.name for s in only.sensors()] == ["adxl345", "extra"]
    assert {p.name: p.status for p in only.plugins()}["lr"] == "not selected"


def test_trace_switch_prints_registrations(capsys):
    build_registry(environ={"SDT_TRACE_HOOKS": "1", "SDT_PLUGINS": "adxl345"})
    assert "adxl345 registered sensor 'adxl345'" in capsys.readouterr().err


@pytest.mark.parametrize(
    "hook", ["register_sensors", "register_features", "register_classifiers", "register_datasets"]
)
def test_hook_kinds_reject_the_wrong_spec_type(hook):
    module = types.ModuleType(f"wrong_{hook}")

    def impl(register):
        register(object())

    setattr(module, hook, hookimpl(impl))
    info = build_registry(entry_points=False).register_plugin(module)
    assert info.status == "error" and "registered object, expected" in info.error
