"""sdt explore's battery-life objective (issue 34 hook): each point's life and the 3-way front."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from sdt_framework import build_registry
from sdt_framework.bench import run_plan_folder
from sdt_framework.edge.cells import cell
from sdt_framework.edge.life_objective import non_dominated
from sdt_framework.edge.node import NodeSettings, node_budget
from sdt_framework.explore.output import write_explore
from sdt_framework.explore.run import explore_table, plan_explore
from sdt_framework.explore.sweep_file import parse_sweep

from ..helpers import small_protocol

PROTOCOL = small_protocol()
SWEEP = {
    "base": "adxl345",
    "axes": {"noise_density_ug_rthz": {"levels": [90, 290]}},
    "target": {"max_loss": 0.1},
}


def test_pareto_csv_carries_battery_life_and_the_front_with_it(tmp_path):
    registry = build_registry()
    protocol = {**PROTOCOL, "cache_dir": str(tmp_path / "cache")}
    explore = plan_explore(parse_sweep(SWEEP), protocol, {}, registry)
    out = tmp_path / "out"
    results = run_plan_folder(explore.plan, out).results
    write_explore(explore, explore_table(explore, results), out)
    pareto = pd.read_csv(out / "pareto.csv")
    points = pd.read_csv(out / "points.csv")
    # the points keep the ADXL345's supply figures: the life of the adxl345 node itself
    expected = node_budget(
        registry.sensor("adxl345"),
        explore.plan.feature_set,
        cell("2xAA"),
        NodeSettings(window_s=explore.plan.config.window_s),
    ).life_years
    assert points["battery_life_years"].to_numpy() == pytest.approx([expected, expected])
    for _, part in pareto.groupby(["machine", "scenario", "classifier"]):
        objectives = part[["cost", "macro_f1", "battery_life_years"]].to_numpy(float)
        mask = non_dominated(objectives * np.array([1.0, -1.0, -1.0]))
        assert part["on_front_with_life"].tolist() == mask.tolist()
