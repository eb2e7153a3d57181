"""Battery cells (issue 40, item 6): self-discharge, capacity at the node's drain, shelf-life cap.

Every expected life here is worked out by hand from the sources' numbers
(cells.toml quotes them), not read back from the code under test.
"""

from __future__ import annotations

import math
import re

import pytest

from sdt_framework.edge.cells import CELL_ENTRIES, CELLS, cell, cell_life
from sdt_framework.edge.node import NodeSettings, node_budget
from sdt_framework.specs.supply import printed_numbers

#: the shelf lives the sources state: Energizer L91 "Shelf Life: 15 years at 21°C";
#: Linden's Table 14.1, soluble-cathode (Li/SOCl2) lithium cells "5–20" years
STATED_SHELF_LIFE = {"2xAA": 15.0, "C": 20.0, "D": 20.0}
#: the reporting intervals users try, s
INTERVALS = [60, 300, 600, 1800, 3600, 6 * 3600, 86400]


def _numbers(text: str) -> list[float]:
    """The printed numbers, with units glued to them ("7.7Ah", "120MHz") split off."""
    return printed_numbers(re.sub(r"(\d)([^\d\s.,;|)])", r"\1 \2", text))


def _has(numbers: list[float], value: float) -> bool:
    return any(math.isclose(n, value, rel_tol=1e-12) for n in numbers)


def test_every_cell_figure_is_in_its_printed_words():
    for entry in CELL_ENTRIES.values():
        cap = entry.capacity.source
        scale = 1e-3 if cap.printed_unit == "Ah" else 1.0
        printed = _numbers(cap.printed)
        points = entry.capacity.curve or [(entry.capacity.rated_drain_ma, entry.capacity.mah)]
        if entry.capacity.curve:
            for drain, mah in points:  # every point of the curve, drain and capacity
                assert _has(printed, drain) and _has(printed, mah * scale), (entry.name, drain)
        else:
            assert _has(printed, entry.capacity.mah * scale), entry.name
        sd = entry.self_discharge
        pct = sd.lost_pct if sd.lost_pct is not None else sd.retained_pct
        assert pct in _numbers(sd.source.printed) and sd.years in _numbers(sd.source.printed)
        assert entry.shelf_life.value in _numbers(entry.shelf_life.printed), entry.name
        for figure in (cap, sd.source, entry.shelf_life):
            assert figure.doc and figure.where


def test_every_cell_has_a_self_discharge_and_a_shelf_life():
    assert cell("2xAA").self_discharge_per_year == pytest.approx(0.10 / 15)  # 90 % after 15 y
    assert cell("C").self_discharge_per_year == pytest.approx(0.01)  # "less than 1 %" a year
    assert cell("D").self_discharge_per_year == pytest.approx(0.01)  # "less than 1% per year"
    for battery in CELLS.values():
        assert battery.shelf_life_years == STATED_SHELF_LIFE[battery.name]


def test_d_cell_at_a_known_drain_by_hand():
    """Linden Fig. 14.17: 17 Ah at 0.2 mA, 18.4 Ah at 1 mA; 1 %/year; capped at 20 years."""
    # 0.5 mA lies between 0.2 and 1 mA: log-interpolated, ln(2.5)/ln(5) of the way
    fraction = math.log(0.5 / 0.2) / math.log(1.0 / 0.2)
    capacity = 17000 + fraction * (18400 - 17000)  # 17797 mAh
    expected = 1 / (0.5 * 8766 / capacity + 0.01)  # 1 / (0.24627 + 0.01) = 3.90 years
    life = cell_life(0.5e-3, cell("D"))
    assert life.capacity_mah == pytest.approx(capacity)
    assert life.years == pytest.approx(expected, rel=1e-12)
    assert life.years == pytest.approx(3.902, abs=1e-3)
    # a node's 50 uA: below the curve's 0.2 mA the 17 Ah hold; the drain alone gives
    # 1 / (0.05 x 8766 / 17000 + 0.01) = 27.95 years, more than the 20-year shelf life
    node = cell_life(50e-6, cell("D"))
    assert node.uncapped_years == pytest.approx(1 / (0.05 * 8.766 / 17 + 0.01), rel=1e-12)
    assert node.capped and node.years == 20.0


def test_c_cell_follows_the_bobbin_curve_scaled_to_its_rating():
    # 7.7 Ah at 4 mA (Saft); the D curve's shape: 17 Ah / 19 Ah at 0.2 mA and below
    assert cell("C").capacity_at(4e-3) == pytest.approx(7700.0)
    assert cell("C").capacity_at(50e-6) == pytest.approx(7700 * 17 / 19)
    expected = 1 / (0.05 * 8766 / (7700 * 17 / 19) + 0.01)  # 15.4 years
    assert cell_life(50e-6, cell("C")).years == pytest.approx(expected, rel=1e-12)


def test_2xaa_at_a_known_drain_by_hand():
    # 3000 mAh flat, 10 % in 15 years: at 37 uA, 1 / (0.037 x 8766 / 3000 + 0.1 / 15)
    expected = 1 / (0.037 * 8766 / 3000 + 0.1 / 15)
    assert cell_life(37e-6, cell("2xAA")).years == pytest.approx(expected, rel=1e-12)
    # at 6 uA the drain alone would give 1 / (0.006 x 8.766 / 3 + 0.00667) = 41.3 years
    low = cell_life(6e-6, cell("2xAA"))
    assert low.capped and low.years == 15.0


@pytest.mark.parametrize("sensor_name", ["adxl345", "adxl357", "lis3dh", "iis3dwb"])
def test_no_life_above_the_stated_shelf_life_at_any_interval(registry, paper8, sensor_name):
    sensor = registry.sensor(sensor_name)
    for name, cap in STATED_SHELF_LIFE.items():
        for interval in INTERVALS:
            for axes, rate in ((3, None), (1, "DR5")):
                settings = NodeSettings(interval_s=interval, axes=axes, data_rate=rate)
                budget = node_budget(sensor, paper8, cell(name), settings)
                assert budget.life_years <= cap, (sensor_name, name, interval, axes)
                if budget.life_capped:
                    assert any("shelf life" in note for note in budget.notes)


@pytest.mark.parametrize("interval", ["10min", "1h", "1d"])
def test_the_printed_life_never_exceeds_the_stated_shelf_life(interval):
    """What `sdt budget --sensor` prints: before, a D cell at 1 h read "> 100 years"."""
    from typer.testing import CliRunner

    from sdt_framework.cli.main import app

    for name, cap in STATED_SHELF_LIFE.items():
        args = ["budget", "--sensor", "adxl345", "--battery", name, "--interval", interval]
        result = CliRunner().invoke(app, args, env={"COLUMNS": "200"})
        assert result.exit_code == 0, result.output
        printed = re.search(r"battery life (\S+) years", result.stdout)[1]
        assert printed != "> 100" and float(printed) <= cap, (name, interval, printed)
        if float(printed) == cap:
            assert f"capped at the {name} cell's rated shelf life" in result.stdout
