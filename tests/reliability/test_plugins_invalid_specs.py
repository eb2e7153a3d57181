"""A plugin registering invalid specs: one line per invalid spec, its valid specs still count."""

from __future__ import annotations

from sdt_framework import build_registry

GOOD = dict(
    sampling_rate_hz=1000,
    full_scale_g=2,
    adc_bits=10,
    noise_density_ug_rthz=100,
    mech_cutoff_hz=3000,
    analog_cutoff_hz=400,
)

MIXED = f"""
from sdt_framework import ClassifierSpec, hookimpl

GOOD = {GOOD!r}

@hookimpl
def register_sensors(register):
    register({{**GOOD, "name": "good-one"}})
    register({{**GOOD, "name": "bad-bits", "adc_bits": 0}})
    register({{**GOOD, "name": "bad-two", "sampling_rate_hz": -5, "colour": "red"}})
    register({{**GOOD, "name": "good-two"}})

@hookimpl
def register_classifiers(register):
    register(ClassifierSpec(name="mixed-lr", estimator="sklearn.linear_model:LogisticRegression"))
"""

BUILDS_INVALID = f"""
from sdt_framework import SensorSpec, hookimpl

GOOD = {GOOD!r}

@hookimpl
def register_sensors(register):
    register(SensorSpec(**GOOD, name="kept"))
    register(SensorSpec(**{{**GOOD, "adc_bits": 99}}, name="too-many-bits"))
"""

INVALID_AT_IMPORT = f"""
from sdt_framework import SensorSpec, hookimpl

BAD = SensorSpec(**{{**{GOOD!r}, "full_scale_g": 0}}, name="zero")
"""


def test_valid_specs_of_a_plugin_with_invalid_ones_are_registered(fake_dist):
    fake_dist("sdt-mixed", {"mixed": "mixed_mod"}, {"mixed_mod": MIXED})
    registry = build_registry(environ={"SDT_PLUGINS": "mixed"})
    assert [s.name for s in registry.sensors()] == ["good-one", "good-two"]
    assert registry.sensor("good-two").distribution == "sdt-mixed"
    assert [c.name for c in registry.classifiers()] == ["mixed-lr"]
    [info] = [p for p in registry.plugins() if p.name == "mixed"]
    assert info.status == "partial"
    assert info.provides == {"sensor": ["good-one", "good-two"], "classifier": ["mixed-lr"]}


def test_one_line_per_invalid_spec_naming_plugin_distribution_spec_field_reason(fake_dist):
    fake_dist("sdt-mixed", {"mixed": "mixed_mod"}, {"mixed_mod": MIXED})
    lines = build_registry(environ={"SDT_PLUGINS": "mixed"}).problems()
    assert len(lines) == 2
    first, second = lines
    assert first.startswith("plugin 'mixed' (sdt-mixed): invalid sensor 'bad-bits': ")
    assert "field 'adc_bits': Input should be greater than or equal to 1" in first
    assert second.startswith("plugin 'mixed' (sdt-mixed): invalid sensor 'bad-two': ")
    assert "field 'sampling_rate_hz': Input should be greater than 0" in second
    assert "field 'colour': unknown field" in second
    assert all("\n" not in line and "not registered" in line for line in lines)


def test_a_spec_the_plugin_builds_invalid_itself_keeps_earlier_ones(fake_dist):
    fake_dist("sdt-builder", {"builder": "builder_mod"}, {"builder_mod": BUILDS_INVALID})
    registry = build_registry(environ={"SDT_PLUGINS": "builder"})
    assert [s.name for s in registry.sensors()] == ["kept"]
    [line] = registry.problems()
    assert line.startswith(
        "plugin 'builder' (sdt-builder): register_sensors built an invalid SensorSpec: "
        "field 'adc_bits': Input should be less than or equal to 32"
    )


def test_invalid_spec_at_import_is_one_line(fake_dist):
    fake_dist("sdt-imp", {"imp": "imp_mod"}, {"imp_mod": INVALID_AT_IMPORT})
    [line] = build_registry(environ={"SDT_PLUGINS": "imp"}).problems()
    assert line == (
        "plugin 'imp' (sdt-imp): import of imp_mod failed: "
        "field 'full_scale_g': Input should be greater than 0"
    )


def test_cli_warns_one_line_each_and_uses_the_valid_specs(fake_dist, monkeypatch, sdt_main):
    fake_dist("sdt-mixed", {"mixed": "mixed_mod"}, {"mixed_mod": MIXED})
    status, out, err = sdt_main("sensors", "show", "good-two", "--json")
    assert status == 0
    assert '"name": "good-two"' in out
    lines = err.splitlines()
    assert len(lines) == 2 and all(line.startswith("warning: plugin 'mixed'") for line in lines)
