"""`sdt budget`: the table, JSON for scripts, and one-line errors."""

from __future__ import annotations

import json
import re

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
        (["--interval", "abc"], "error: --interval 'abc' is not a duration"),
        (["--axes", "0"], "error: --axes must be 1 or more, got 0"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(sdt_main, args, message):
    assert _one_line_exit_2(sdt_main, *args).startswith(message)


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


def _one_line_exit_2(sdt_main, *args: str) -> str:
    """``sdt budget ARGS`` (in this process: refused before any work): its one stderr line."""
    code, _, err = sdt_main("budget", *args)
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2 and len(lines) == 1, (code, err)
    return lines[0]


@pytest.mark.parametrize(
    ("args", "message"),
    [
        # a bare number: 10 s or 10 min? refused, not guessed (issue 39)
        (["--interval", "10"], "error: --interval '10' has no unit; write 10s (seconds), 10min"),
        (["--sensor", "adxl345", "--window", "0.64"], "error: --window '0.64' has no unit"),
        # node options without --sensor would be ignored (issue 39)
        (["--battery", "D"], "error: --battery needs --sensor"),
        (["--capacity-mah", "2600"], "error: --capacity-mah needs --sensor"),
        (["--dr", "DR5"], "error: --dr needs --sensor"),
        # cell figures without a cell of one's own would be ignored; a zero voltage refused
        (
            ["--sensor", "adxl345", "--cell-voltage", "0"],
            "error: --cell-voltage needs --capacity-mah",
        ),
        (
            ["--sensor", "adxl345", "--capacity-mah", "2600", "--cell-voltage", "0",
             "--self-discharge-pct", "1", "--shelf-life-years", "10"],
            "error: --cell-voltage must be > 0 V, got 0.0",
        ),
        # a cell of one's own needs the figures the life depends on: none is guessed
        (
            ["--sensor", "adxl345", "--capacity-mah", "2600"],
            "error: --capacity-mah needs --cell-voltage, --self-discharge-pct, --shelf-life-years",
        ),
        (["--sensor", "adxl345", "--voltage", "3.3"], "error: --voltage sets the radio table"),
    ],
)  # fmt: skip
def test_values_that_would_be_ignored_or_guessed_are_one_line_exit_2(sdt_main, args, message):
    assert _one_line_exit_2(sdt_main, *args).startswith(message)


def test_own_cell_with_its_figures_is_used_and_capped(paper8):
    args = ["budget", "--sensor", "adxl345", "--capacity-mah", "2600", "--cell-voltage", "3.6",
            "--self-discharge-pct", "1", "--shelf-life-years", "10", "--interval", "1h",
            "--json"]  # fmt: skip
    data = json.loads(runner.invoke(app, args).stdout)
    assert data["battery"]["capacity_mah"] == 2600 and data["battery"]["shelf_life_years"] == 10
    average_ma = data["average_current_a"] * 1e3
    uncapped = 1 / (average_ma * 8766 / 2600 + 0.01)
    assert data["uncapped_life_years"] == pytest.approx(uncapped, rel=1e-12)
    assert data["life_years"] == min(10.0, uncapped)


def test_help_examples_name_only_registered_feature_sets(registry):
    """`sdt budget --help` suggested 'paper8+env_bpfo', which no default install has (issue 39)."""
    from sdt_framework.features import resolve_feature_set

    text = runner.invoke(app, ["budget", "--help"], env={"COLUMNS": "200"}).stdout
    names = set(re.findall(r"\b[a-z][a-z0-9_]*(?:\+[a-z][a-z0-9_]*)+\b", text))
    names |= set(re.findall(r"--features (\S+)", text))
    assert "paper8" in names or "--features paper8" in text
    for name in names:
        resolve_feature_set(registry, name)  # raises on a set that is not registered
