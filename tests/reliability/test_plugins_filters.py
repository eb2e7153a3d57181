"""The plugin switches say when they matter: a name matching nothing installed is a warning,
and a name not found while a switch left plugins out says that the switch is active."""

from __future__ import annotations

import pytest

from sdt_framework import UnknownNameError, build_registry

SENSOR_PLUGIN = """
from sdt_framework import SensorSpec, hookimpl

@hookimpl
def register_sensors(register):
    register(SensorSpec(name="extra", sampling_rate_hz=1000, full_scale_g=2, adc_bits=10,
                        noise_density_ug_rthz=100, mech_cutoff_hz=3000, analog_cutoff_hz=400))
"""


def test_only_switch_naming_nothing_installed_warns():
    registry = build_registry(environ={"SDT_PLUGINS": "adxl3455"})
    assert registry.sensors() == []
    [line] = registry.problems()
    assert line.startswith("SDT_PLUGINS='adxl3455': no installed plugin or distribution is ")
    assert "called 'adxl3455', so no plugin is loaded" in line
    assert "installed plugins: " in line and "adxl345" in line


def test_only_switch_with_some_unknown_names_warns_about_those_only():
    registry = build_registry(environ={"SDT_PLUGINS": "adxl345, nope ,paper8,Sdt-Framework"})
    [line] = registry.problems()
    assert "called 'nope', so only the other names are loaded" in line
    assert "'adxl345'" not in line and "'paper8'" not in line


def test_block_switch_naming_nothing_installed_warns():
    [line] = build_registry(environ={"SDT_BLOCK_PLUGINS": "adxl354"}).problems()
    assert "SDT_BLOCK_PLUGINS='adxl354'" in line and "nothing is blocked by them" in line


def test_known_names_give_no_warning(fake_dist):
    fake_dist("sdt-extra", {"extra-sensor": "extra_mod"}, {"extra_mod": SENSOR_PLUGIN})
    environ = {"SDT_PLUGINS": "extra-sensor,sdt-framework", "SDT_BLOCK_PLUGINS": "sdt_extra"}
    assert build_registry(environ=environ).problems() == []


def test_unknown_name_under_a_block_switch_names_the_switch():
    registry = build_registry(environ={"SDT_BLOCK_PLUGINS": "adxl345"})
    with pytest.raises(UnknownNameError) as info:
        registry.sensor("adxl345")
    message = str(info.value)
    assert "unknown sensor 'adxl345'" in message
    assert "A plugin filter is active (SDT_BLOCK_PLUGINS='adxl345') and left out: adxl345;" in (
        message
    )


def test_unknown_name_under_an_only_switch_names_the_switch():
    registry = build_registry(environ={"SDT_PLUGINS": "lr"})
    with pytest.raises(UnknownNameError, match=r"filter is active \(SDT_PLUGINS='lr'\)"):
        registry.feature_set("paper8")


def test_no_note_without_a_switch():
    with pytest.raises(UnknownNameError) as info:
        build_registry(environ={}).sensor("nope")
    assert "filter" not in str(info.value)


def test_cli_prints_the_warning_and_the_filter_in_the_error(monkeypatch, sdt_main):
    monkeypatch.setenv("SDT_PLUGINS", "adxl357,adxl3455")
    status, _, err = sdt_main("sensors", "show", "adxl345")
    assert status == 2
    warning, error = err.splitlines()
    assert warning.startswith("warning: SDT_PLUGINS='adxl357,adxl3455': no installed plugin")
    assert error.startswith("error: unknown sensor 'adxl345'. Did you mean 'adxl357'?")
    assert "A plugin filter is active (SDT_PLUGINS='adxl357,adxl3455') and left out:" in error
