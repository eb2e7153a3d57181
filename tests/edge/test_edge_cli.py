"""`sdt budget`: the table, JSON for scripts, and one-line errors."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from sdt_framework import SDTError
from sdt_framework.cli.main import app

runner = CliRunner()


def test_default_budget_is_paper8_triaxial_every_10_min_in_eu868():
    result = runner.invoke(app, ["budget"], env={"COLUMNS": "160"})
    assert result.exit_code == 0, result.output
    out = result.stdout
    assert "paper8: 8 features x float32 = 32 B/axis x 3 axes = 96 B per report" in out
    assert "every 10min (144 reports/day); EU868, duty cycle 1%" in out
    lines = {line.split()[0]: line.split() for line in out.splitlines() if line[:2] == "DR"}
    assert lines["DR0"][1:5] == ["SF12/125", "51", "no", "2"]
    assert lines["DR5"][1:6] == ["SF7/125", "222", "yes", "1", "184.6"]


def test_json_float16_us915():
    result = runner.invoke(
        app, ["budget", "--dtype", "float16", "--region", "US915", "--interval", "1h", "--json"]
    )
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert (data["app_payload_bytes"], data["reports_per_day"], data["region"]) == (48, 24, "US915")
    assert [row["fits"] for row in data["rows"]] == [False, True, True, True, True]
    assert data["radio"]["tx_current_a"] == 0.029


def test_radio_override_scales_energy():
    base = json.loads(runner.invoke(app, ["budget", "--json"]).stdout)
    mine = json.loads(
        runner.invoke(app, ["budget", "--json", "--tx-current-ma", "58", "--voltage", "3.3"]).stdout
    )
    assert mine["rows"][5]["energy_per_day_j"] == pytest.approx(
        2 * base["rows"][5]["energy_per_day_j"]
    )


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--region", "XX"], "error: unknown region 'XX'"),
        (["--interval", "abc"], "error: interval 'abc' is not a duration"),
        (["--axes", "0"], "error: --axes must be 1 or more, got 0"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(args, message):
    result = subprocess.run(
        [sys.executable, "-m", "sdt_framework", "budget", *args],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith(message), result.stderr


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--features", "paper9"], "unknown feature set 'paper9'"),
        (["--dtype", "float8"], "--dtype must be float16 or float32"),
        (["--voltage", "-1"], "supply_v must be positive"),
    ],
)
def test_other_bad_input_raises_the_user_error(args, message):
    result = runner.invoke(app, ["budget", *args])
    assert isinstance(result.exception, SDTError)  # main() prints it as one line, exit 2
    assert message in str(result.exception)
