"""`sdt sensors list` filters and mode options, `sdt sensors show` provenance, mode errors."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from sdt_framework.cli.main import app

pytestmark = pytest.mark.catalog


def listed(*options: str) -> dict[str, dict]:
    result = CliRunner().invoke(app, ["sensors", "list", *options, "--json"])
    assert result.exit_code == 0, result.output
    return {entry["name"]: entry for entry in json.loads(result.stdout)}


def test_parts_are_listed_with_their_mode_options():
    parts = {n: e for n, e in listed().items() if e["kind"] == "part"}
    adxl355 = parts["adxl355"]
    assert adxl355["modes"]["range"] == {
        "options": ["2g", "4g", "8g"],
        "default": "2g",
        "why": adxl355["modes"]["range"]["why"],
    }
    assert adxl355["default_sensor"] == "adxl355[odr=4000,range=2g]"
    assert adxl355["noise_x_ug_rthz"] == [22.5, 25.0]
    assert adxl355["documents"]["ds"]["revision"] == "Rev. D (6/2025)"


def test_max_price_keeps_priced_parts_at_or_below_it():
    assert set(listed("--max-price", "5EUR")) == {"adxl345-ds"}  # 3.92 EUR
    assert set(listed("--max-price", "15")) == {"adxl345-ds", "adxl372", "iis3dwb"}
    assert set(listed("--max-price", "100USD")) == set()  # prices are in EUR


def test_min_rate_max_noise_and_simulable_at():
    fast = listed("--min-rate", "20000")
    assert {"adxl1002", "iim42352", "iis3dwb", "kx134", "wilcoxon-786b10"} <= set(fast)
    assert not {"adxl355", "mpu6050", "adxl345"} & set(fast)
    assert fast["kx134"]["matching_modes"][0].startswith("kx134[lpf=odr9,odr=25600,")
    quiet = {n for n, e in listed("--max-noise", "30").items() if e["kind"] == "part"}
    assert quiet == {"adxl1002", "adxl355"}  # 25 and 22.5 ug/sqrt(Hz)
    at_12k = listed("--simulable-at", "12000")
    assert "iis3dwb" not in at_12k and "wilcoxon-786b10" not in at_12k
    assert {"adxl355", "mpu6050", "native-reference", "adxl345"} <= set(at_12k)
    # a 26.667 kHz part is simulable from 51.2 kHz recordings
    assert "iis3dwb" in listed("--simulable-at", "51200")


def test_show_prints_the_provenance_of_every_value():
    result = CliRunner().invoke(app, ["sensors", "show", "adxl355[range=4g]", "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["sensor"]["name"] == "adxl355[odr=4000,range=4g]"
    sources = {s["field"]: s for s in data["provenance"]}
    assert sources["noise_density_ug_rthz"]["absent"].startswith("Table 2 gives")
    assert sources["noise_density_ug_rthz"]["value"] == 25
    assert sources["digital_cutoff_hz"]["odr_fraction"] == 0.25
    assert sources["full_scale_g"]["set_by"] == "range=4g"
    table = CliRunner().invoke(
        app, ["sensors", "show", "adxl355[range=4g]"], env={"COLUMNS": "200"}
    )
    assert "adxl355[odr=4000,range=4g]" in table.stdout  # brackets survive rich markup
    assert "not in the documents" in table.stdout


def test_an_invalid_mode_is_one_line_and_exit_2():
    result = subprocess.run(
        [sys.executable, "-m", "sdt_framework", "sensors", "show", "adxl355[range=3g]"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    assert result.stderr.strip() == (
        "error: part 'adxl355': range=3g is not an option; range is one of 2g, 4g, 8g"
    )
