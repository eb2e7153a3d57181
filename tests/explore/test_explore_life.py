"""Battery life as a sweep constraint: the minimum specification, meeting points, bad values.

The lives are the node model's for the ADXL345 at each sampling rate (a faster
part's window has more samples for the microcontroller's FFT: the life falls
with the rate, checked here first); thresholds are then placed between two of
those lives, so which points meet is known by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from sdt_framework.edge.cells import cell
from sdt_framework.edge.node import NodeSettings, node_budget
from sdt_framework.explore import min_spec
from sdt_framework.explore.life import point_lives
from sdt_framework.explore.minspec import meeting_points
from sdt_framework.explore.objectives import verdicts
from sdt_framework.explore.target import Target

RATES = [800.0, 1600.0, 3200.0, 6400.0]
FIELDS = ["sampling_rate_hz"]
DEMAND = {"sampling_rate_hz": "higher"}
BASE = {"sampling_rate_hz": 3200.0}
WINDOW_S = 0.64


@pytest.fixture(scope="module")
def lives(registry) -> dict[float, float]:
    """The ADXL345 node's life (2xAA, a report per 10 min) with the part at each rate."""
    base = registry.sensor("adxl345")
    specs = [base.model_copy(update={"name": f"r{r:g}", "sampling_rate_hz": r}) for r in RATES]
    table = point_lives(specs, registry.feature_set("paper8"), WINDOW_S, Target(max_loss=0.05))
    assert (table["life_note"] == "").all()
    return dict(zip(RATES, table["battery_life_years"], strict=True))


def test_the_lives_are_the_node_models_and_fall_with_the_rate(registry, lives) -> None:
    base = registry.sensor("adxl345")
    fast = base.model_copy(update={"sampling_rate_hz": 6400.0})
    settings = NodeSettings(interval_s=600.0, window_s=WINDOW_S)
    direct = node_budget(fast, registry.feature_set("paper8"), cell("2xAA"), settings)
    assert lives[6400.0] == direct.life_years
    values = [lives[r] for r in RATES]
    assert values == sorted(values, reverse=True) and len(set(values)) == 4


def _tidy(lives: dict[float, float], f1: dict[float, float]) -> pd.DataFrame:
    """One cell, a point per rate with the given Macro F1 and life; reference 0.9."""
    rows = [{"point": "ref", "role": "reference", "rate": np.nan, "macro_f1": 0.9, "life": np.nan}]
    rows += [
        {"point": f"r{r:g}", "role": "point", "rate": r, "macro_f1": f1[r], "life": lives[r]}
        for r in RATES
    ]
    frame = pd.DataFrame(rows).rename(
        columns={"rate": "sampling_rate_hz", "life": "battery_life_years"}
    )
    return frame.assign(machine="Motor-4", scenario="forward", classifier="lr", repeat=0)


#: Macro F1 reaches the target (loss <= 0.05 to 0.9) from 1600 Hz up
F1 = {800.0: 0.70, 1600.0: 0.88, 3200.0: 0.89, 6400.0: 0.90}


def test_a_threshold_between_two_lives_moves_the_minimum_specification(lives) -> None:
    table = _tidy(lives, F1)
    f1_only = min_spec(table, FIELDS, BASE, Target(max_loss=0.05), DEMAND)
    assert f1_only["min_level"].tolist() == [1600.0]
    # between the 1600 Hz and the 800 Hz node: 1600 Hz no longer lasts long enough,
    # and a faster part lasts even less, so no rate meets both
    between = (lives[800.0] + lives[1600.0]) / 2
    target = Target(max_loss=0.05, min_battery_life_years=between)
    both = min_spec(table, FIELDS, BASE, target, DEMAND)
    assert math.isnan(both["min_level"].iloc[0])
    assert both["min_level_macro_f1"].tolist() == [1600.0]
    assert both["min_level_life"].tolist() == [800.0]  # life alone: the slowest part
    assert both["note"].iloc[0] == "no level meets the target"
    assert meeting_points(table, FIELDS, target).empty


def test_life_is_asked_of_the_chosen_level_not_of_every_faster_one(lives) -> None:
    """Between the 3200 and 1600 Hz lives: 3200 and 6400 fail, 1600 still answers."""
    table = _tidy(lives, F1)
    target = Target(max_loss=0.05, min_battery_life_years=(lives[1600.0] + lives[3200.0]) / 2)
    spec = min_spec(table, FIELDS, BASE, target, DEMAND)
    assert spec["min_level"].tolist() == [1600.0]
    judged = verdicts(table, FIELDS, target).set_index("point")
    assert judged["meets_life"].to_dict() == {
        "r800": True,
        "r1600": True,
        "r3200": False,
        "r6400": False,
    }
    assert judged["meets"].to_dict() == {
        "r800": False,  # lasts, but diagnoses too poorly
        "r1600": True,
        "r3200": False,
        "r6400": False,
    }
    assert meeting_points(table, FIELDS, target)["point"].tolist() == ["r1600"]


def test_a_threshold_every_point_meets_changes_nothing(lives) -> None:
    table = _tidy(lives, F1)
    below_all = min(lives.values()) / 2
    f1_only = Target(max_loss=0.05)
    with_life = Target(max_loss=0.05, min_battery_life_years=below_all)
    a = min_spec(table, FIELDS, BASE, f1_only, DEMAND)
    b = min_spec(table, FIELDS, BASE, with_life, DEMAND)
    assert b["min_level"].tolist() == a["min_level"].tolist() == [1600.0]
    assert b["min_level_life"].tolist() == [800.0]
    kept = ["point", "macro_f1"]
    pd.testing.assert_frame_equal(
        meeting_points(table, FIELDS, f1_only)[kept], meeting_points(table, FIELDS, with_life)[kept]
    )


def test_a_point_without_supply_figures_cannot_meet_a_life_constraint(registry, lives) -> None:
    bare = registry.sensor("adxl345").model_copy(update={"name": "bare", "supply": None})
    table = point_lives([bare], registry.feature_set("paper8"), WINDOW_S, Target(max_loss=0.05))
    assert math.isnan(table["battery_life_years"].iloc[0])
    assert table["life_note"].iloc[0] == "no supply figures on record"
    unknown = _tidy(dict.fromkeys(RATES, math.nan), F1)
    target = Target(max_loss=0.05, min_battery_life_years=0.1)
    assert not verdicts(unknown, FIELDS, target)["meets"].any()
    spec = min_spec(unknown, FIELDS, BASE, target, DEMAND)
    assert math.isnan(spec["min_level"].iloc[0])
    assert "have no battery life (points.csv, life_note, says why)" in spec["note"].iloc[0]


def test_the_target_says_battery_and_interval() -> None:
    target = Target(max_loss=0.05, min_battery_life_years=5.0, battery="C", report_interval="1h")
    assert target.describe() == (
        "loss to reference <= 0.05 and battery life >= 5 years (C, a report per 1 h)"
    )
    assert target.interval_s == 3600.0


SWEEP = """[sweep]
base = "adxl345"
[sweep.axes]
sampling_rate_hz = {{ levels = [800, 3200] }}
[sweep.target]
max_loss = 0.1
{line}
[benchmark]
machines = ["Motor-2"]
"""


@pytest.mark.parametrize(
    ("line", "field"),
    [
        ("min_battery_life_years = -1", "min_battery_life_years"),
        ("min_battery_life_years = 0", "min_battery_life_years"),
        ('min_battery_life_years = "5"', "min_battery_life_years"),
        ("min_battery_life_years = true", "min_battery_life_years"),
        ('battery = "AAA"', "battery"),
        ('report_interval = "10m"', "report_interval"),
        ('report_interval = "0s"', "report_interval"),
        ('report_interval = "10"', "report_interval"),  # no unit: 10 s or 10 min? (issue 39)
        # above the cell's rated shelf life no node can last: refused, not failed at the end
        ('min_battery_life_years = 25\nbattery = "D"', "min_battery_life_years"),
        ("min_battery_life_years = 16", "min_battery_life_years"),  # 2xAA: 15 years
    ],
)
def test_a_bad_life_value_is_one_line_naming_file_and_field(
    sdt_in_process, tmp_path, line, field
) -> None:
    path = tmp_path / "sweep.toml"
    path.write_text(SWEEP.format(line=line))
    result = sdt_in_process("explore", str(path), "--out", str(tmp_path / "o"))  # refused
    assert result.returncode == 2, result.stderr
    lines = [x for x in result.stderr.splitlines() if x.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    assert str(path) in lines[0] and "sweep.target" in lines[0]
    assert field in lines[0]


@pytest.mark.parametrize(
    ("interval", "why"),
    [("2s", "breaks the EU868 duty cycle"), ("0.5s", "shorter than one acquisition")],
)
def test_a_report_interval_the_node_cannot_keep_is_refused_when_the_sweep_is_read(
    sdt_in_process, tmp_path, interval, why
) -> None:
    """Before: the whole sweep ran, then blamed 'no supply current' and suggested --interval."""
    path = tmp_path / "sweep.toml"
    path.write_text(
        SWEEP.format(line=f'min_battery_life_years = 5.0\nreport_interval = "{interval}"')
    )
    out = tmp_path / "o"
    args = ["explore", str(path), "--quick", "--strategy", "exhaustive", "--out", str(out)]
    result = sdt_in_process(*args)  # refused when the sweep is read: in this process
    assert result.returncode == 2, result.stderr
    lines = [x for x in result.stderr.splitlines() if x.strip()]
    assert len(lines) == 1, result.stderr
    assert lines[0].startswith(f"error: {path}: sweep.target.report_interval = '{interval}': ")
    assert why in lines[0] and lines[0].endswith("lengthen report_interval")
    assert "--interval" not in lines[0] and not (out / "results.parquet").exists()


def test_battery_or_interval_without_a_life_threshold_is_said(sdt_in_process, tmp_path) -> None:
    target = Target(max_loss=0.05, battery="D")
    (note,) = target.life_notes()
    assert note.startswith("sweep.target.battery = 'D' without min_battery_life_years")
    assert "no point is judged on it" in note
    assert Target(max_loss=0.05).life_notes() == []
    assert Target(max_loss=0.05, battery="D", min_battery_life_years=5.0).life_notes() == []
    # the command says it on reading the file (this sweep then stops on benchmark.sensors)
    path = tmp_path / "sweep.toml"
    path.write_text(SWEEP.format(line='battery = "D"') + 'sensors = ["adxl345"]\n')
    result = sdt_in_process("explore", str(path), "--out", str(tmp_path / "o"))
    assert result.returncode == 2
    assert f"note: {path}: sweep.target.battery = 'D' without min_battery_life_years" in (
        result.stderr
    )


#: the shelf lives the sources state (cells.toml): L91 15 years; Li/SOCl2 5-20 years (Linden)
STATED_SHELF_LIFE = {"2xAA": 15.0, "C": 20.0, "D": 20.0}


@pytest.mark.parametrize("battery", sorted(STATED_SHELF_LIFE))
def test_the_life_constraint_can_fail_on_every_cell(registry, battery) -> None:
    """A threshold the cell can hold (its shelf life) fails for a node reporting every 5 min.

    Before, the D cell counted no self-discharge and its 4 mA capacity at 40 uA,
    so the ADXL345 node "lasted" 30.7 years at 5 min and met any such threshold.
    """
    target = Target(
        max_loss=0.05,
        min_battery_life_years=STATED_SHELF_LIFE[battery],
        battery=battery,
        report_interval="5min",
    )
    base = registry.sensor("adxl345")
    lives = point_lives([base], registry.feature_set("paper8"), WINDOW_S, target)
    life = float(lives["battery_life_years"].iloc[0])
    assert life < STATED_SHELF_LIFE[battery]
    table = _tidy({r: life for r in RATES}, F1)
    judged = verdicts(table, FIELDS, target)
    assert not judged["meets_life"].any() and not judged["meets"].any()


def test_a_life_the_shelf_life_caps_says_so(registry) -> None:
    """On a D cell at 10 min the drain alone gives 27.6 years; the cell is rated for 20."""
    target = Target(max_loss=0.05, battery="D")
    lives = point_lives(
        [registry.sensor("adxl345")], registry.feature_set("paper8"), WINDOW_S, target
    )
    assert lives["battery_life_years"].iloc[0] == 20.0
    assert lives["life_note"].iloc[0] == "capped at the D cell's 20-year shelf life"
