"""The sampling model in sensor and part files: bad values are one line, exit 2 (issue 40)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from sdt_framework.errors import SpecFileError
from sdt_framework.parts import load_part_text, resolve
from sdt_framework.sensor_files import load_sensor_file

PROFILE = """
name = "my-357"
sampling = "{sampling}"
sampling_rate_hz = 4000
full_scale_g = 40
adc_bits = 20
noise_density_ug_rthz = 90
mech_cutoff_hz = 5500
analog_cutoff_hz = 1500
{digital}
"""
FILTER = "digital_cutoff_hz = 1000\ndigital_order = 8"


pytestmark = pytest.mark.in_process  # ``sensors show`` starts no worker: sdt in this process


def _sdt(sdt, tmp_path: Path, text: str) -> subprocess.CompletedProcess[str]:
    path = tmp_path / "s.toml"
    path.write_text(text)
    return sdt("--sensor-file", str(path), "sensors", "show", "my-357")


def test_a_sensor_file_can_ask_for_the_decimating_model(sdt, tmp_path: Path) -> None:
    path = tmp_path / "s.toml"
    path.write_text(PROFILE.format(sampling="decimate", digital=FILTER))
    (sensor,) = load_sensor_file(path)
    assert sensor.sampling == "decimate"
    shown = _sdt(sdt, tmp_path, PROFILE.format(sampling="decimate", digital=FILTER))
    assert shown.returncode == 0 and "decimate" in shown.stdout


@pytest.mark.parametrize(
    ("sampling", "digital", "message"),
    [
        (
            "decimation",
            FILTER,
            "field 'sampling': Input should be 'sample-then-filter' or 'decimate'",
        ),
        (
            "decimate",
            "",
            "sampling = 'decimate' needs the decimation low-pass: give digital_cutoff_hz",
        ),
    ],
)
def test_a_bad_sampling_is_one_line_naming_the_file(
    sdt, tmp_path, sampling, digital, message
) -> None:
    result = _sdt(sdt, tmp_path, PROFILE.format(sampling=sampling, digital=digital))
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
    assert result.stderr.startswith(f"error: {tmp_path / 's.toml'}: ")
    assert message in result.stderr


PART = """
name = "toy-sd"
manufacturer = "Test"
description = "made-up sigma-delta part"
interface = "digital"

[documents.ds]
title = "Toy data sheet"
revision = "Rev. 1"

[values]
sampling_rate_hz = {{ value = 1000, doc = "ds", where = "T1", basis = "setting" }}
full_scale_g = {{ value = 2, doc = "ds", where = "T1", basis = "nominal" }}
adc_bits = {{ value = 20, doc = "ds", where = "T1", basis = "nominal" }}
noise_density_ug_rthz = {{ value = 25, doc = "ds", where = "T1", basis = "typical" }}
mech_cutoff_hz = {{ value = 2400, doc = "ds", where = "T1", basis = "typical" }}
analog_cutoff_hz = {{ value = 1500, doc = "ds", where = "T1", basis = "nominal" }}
digital_cutoff_hz = {{ {digital}, doc = "ds", where = "T1", basis = "setting" }}
digital_order = {{ value = 8, doc = "ds", where = "T1", basis = "nominal" }}

[sampling]
model = "decimate"
doc = "{doc}"
where = "Filter section"
stopband = "not stated"
"""


def test_a_part_decimates_with_its_source_and_falls_back_without_a_filter() -> None:
    part = load_part_text(PART.format(digital="odr_fraction = 0.25", doc="ds"), "toy.toml")
    resolved = resolve(part)
    assert resolved.sensor.sampling == "decimate"
    (src,) = [s for s in resolved.sources if s.field == "sampling"]
    assert (src.value, src.doc, src.where) == ("decimate", "ds", "Filter section")
    assert "stopband: not stated" in src.note
    bare = resolve(load_part_text(PART.format(digital='value = "none"', doc="ds"), "toy.toml"))
    assert bare.sensor.sampling == "sample-then-filter"
    (src,) = [s for s in bare.sources if s.field == "sampling"]
    assert "no digital low-pass in this mode" in src.note


def test_a_part_citing_a_missing_document_for_its_sampling_is_refused() -> None:
    with pytest.raises(SpecFileError, match="sampling: document 'dx' is not in \\[documents\\]"):
        load_part_text(PART.format(digital="odr_fraction = 0.25", doc="dx"), "toy.toml")


def test_sensors_show_says_the_paper_profiles_are_the_papers_model(sdt, tmp_path: Path) -> None:
    for name, shown in (("adxl357", "sample-then-filter (the paper's model)"),
                        ("adxl345", "sample-then-filter (the paper's model)")):  # fmt: skip
        out = sdt("sensors", "show", name, env={"COLUMNS": "200"}).stdout
        assert shown in out, name
