"""Sensor profiles as TOML files: the same model as Python plugins, precise errors."""

from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from sdt_framework import SpecFileError, build_registry
from sdt_framework.cli.main import app

GOOD = """
name = "my-sensor"
description = "A made-up sensor"
source = "my datasheet"
sampling_rate_hz = 1000
full_scale_g = 4
adc_bits = 12
noise_density_ug_rthz = 150
mech_cutoff_hz = 3000
analog_cutoff_hz = 400
digital_cutoff_hz = 200
digital_order = 2
"""


def write(tmp_path: Path, text: str, name: str = "s.toml") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_toml_sensor_joins_the_registry(tmp_path):
    registry = build_registry(sensor_files=[write(tmp_path, GOOD)])
    spec = registry.sensor("my-sensor")
    assert spec.adc_bits == 12 and spec.distribution == "(sensor file)"
    assert spec.plugin == str(tmp_path / "s.toml")


def test_sensor_path_environment_variable(tmp_path):
    folder = tmp_path / "sensors"
    folder.mkdir()
    write(folder, GOOD)
    registry = build_registry(environ={"SDT_SENSOR_PATH": str(folder)})
    assert registry.sensor("my-sensor").full_scale_g == 4


def test_several_sensors_in_one_file(tmp_path):
    body = GOOD.replace('name = "my-sensor"', "")
    text = f'[[sensor]]\nname = "a"\n{body}\n[[sensor]]\nname = "b"\n{body}'
    registry = build_registry(entry_points=False, sensor_files=[write(tmp_path, text)])
    assert [s.name for s in registry.sensors()] == ["a", "b"]


@pytest.mark.parametrize(
    ("text", "field", "reason"),
    [
        (GOOD.replace("adc_bits = 12", "adc_bits = 0"), "adc_bits", "greater than or equal to 1"),
        (GOOD.replace("adc_bits = 12", 'adc_bits = "twelve"'), "adc_bits", "valid integer"),
        (GOOD + "sample_rate = 3\n", "sample_rate", "unknown field"),
        (GOOD.replace("mech_cutoff_hz = 3000\n", ""), "mech_cutoff_hz", "Field required"),
        (
            GOOD.replace("digital_cutoff_hz = 200", "digital_cutoff_hz = 600"),
            "",
            "at or above the Nyquist frequency 500 Hz",
        ),
    ],
)
def test_bad_field_reports_file_field_and_reason(tmp_path, text, field, reason):
    path = write(tmp_path, text)
    with pytest.raises(SpecFileError) as info:
        build_registry(entry_points=False, sensor_files=[path])
    message = str(info.value)
    assert message.startswith(str(path))
    assert reason in message
    if field:
        assert f"field {field!r}" in message


def test_field_path_inside_a_sensor_array(tmp_path):
    body = GOOD.replace('name = "my-sensor"', "").replace("adc_bits = 12", "adc_bits = -1")
    path = write(tmp_path, f'[[sensor]]\nname = "a"\n{body}')
    with pytest.raises(SpecFileError, match=r"field 'sensor\[0\].adc_bits'"):
        build_registry(entry_points=False, sensor_files=[path])


def test_invalid_toml_and_missing_file(tmp_path):
    with pytest.raises(SpecFileError, match="not valid TOML"):
        build_registry(entry_points=False, sensor_files=[write(tmp_path, "name = ")])
    with pytest.raises(SpecFileError, match="file not found"):
        build_registry(entry_points=False, sensor_files=[tmp_path / "nope.toml"])


def test_cli_sensor_file_option_and_error(tmp_path):
    runner = CliRunner()
    ok = runner.invoke(
        app, ["--sensor-file", str(write(tmp_path, GOOD)), "sensors", "show", "my-sensor", "--json"]
    )
    assert ok.exit_code == 0, ok.output
    assert '"adc_bits": 12' in ok.output
