"""The adaptive strategy end to end: the same minimum specification as the exhaustive run.

A small grid (4 rates x 4 noise densities on Motor-2, 1.5 s acquisitions) is
run both ways on the same data and protocol. The exhaustive run evaluates
every point with the full protocol; the adaptive one screens every point and
runs the full protocol only on the levels its bisection needs. Their
minimum-specification tables must agree cell by cell.
"""

from __future__ import annotations

import textwrap

import numpy as np
import pandas as pd
import pytest

from sdt_framework import build_registry
from sdt_framework.bench import run_plan_folder
from sdt_framework.explore.adaptive import SCREEN_CLASSIFIERS, Adaptive, budget
from sdt_framework.explore.output import write_explore
from sdt_framework.explore.run import explore_table, plan_explore
from sdt_framework.explore.sweep_file import parse_sweep

from ..helpers import small_protocol

PROTOCOL = small_protocol(channels=2, repeats=2, scenarios=2)
SWEEP = {
    "base": "adxl345",
    "axes": {
        "sampling_rate_hz": {"levels": [800, 1600, 3200, 6400]},
        "noise_density_ug_rthz": {"levels": [25, 90, 290, 1000]},
    },
    "ties": {"digital_cutoff_hz": "rate / 2 - 1"},
    "target": {"max_loss": 0.2},
}
KEYS = ["machine", "scenario", "classifier", "parameter"]


@pytest.fixture(scope="module")
def both(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("adaptive")
    protocol = {**PROTOCOL, "cache_dir": str(tmp / "cache")}
    registry = build_registry()
    explore = plan_explore(parse_sweep(SWEEP), protocol, {}, registry)
    table = explore_table(explore, run_plan_folder(explore.plan, tmp / "exhaustive").results)
    exhaustive = write_explore(explore, table, tmp / "exhaustive")
    adaptive = Adaptive(explore, registry, tmp / "adaptive").run()
    return explore, exhaustive, adaptive, tmp


def test_adaptive_min_spec_equals_the_exhaustive_full_protocol_answer(both):
    _, exhaustive, adaptive, _ = both
    ours = adaptive["min_spec"].set_index(KEYS).sort_index()
    theirs = exhaustive["min_spec"].set_index(KEYS).sort_index()
    assert ours.index.equals(theirs.index)
    np.testing.assert_array_equal(ours["min_level"].to_numpy(), theirs["min_level"].to_numpy())
    np.testing.assert_array_equal(ours["threshold"].to_numpy(), theirs["threshold"].to_numpy())
    assert set(ours["fidelity"]) == {"full"}
    # not a trivial sweep: some answer is a level other than the least demanding one
    levels = theirs["min_level"].dropna()
    assert ((levels != 800) & (levels != 1000)).any(), theirs


def test_adaptive_runs_the_full_protocol_only_on_lines_through_the_base(both):
    explore, _, adaptive, tmp = both
    refined = adaptive["refinement"]
    base = explore.base_values()
    params = pd.read_csv(tmp / "adaptive" / "full" / "points.csv").set_index("point")
    for row in refined.itertuples():
        others = [f for f in SWEEP["axes"] if f != row.parameter]
        assert all(np.isclose(params.loc[row.point, f], base[f]) for f in others)
    at_most, _ = budget(explore)
    assert refined["point"].nunique() <= at_most == 7 < len(explore.points)
    full = pd.read_csv(tmp / "adaptive" / "full" / "results.csv")
    assert set(full["classifier"]) == {"lr"} and full["repeat"].nunique() == 2


def test_the_screen_covers_every_point_and_the_ranking_says_screen(both):
    explore, _, _, tmp = both
    screen = pd.read_csv(tmp / "adaptive" / "screen" / "results.csv")
    assert set(screen["classifier"]) == set(SCREEN_CLASSIFIERS)
    assert screen["repeat"].nunique() == 1
    assert {p.spec.name for p in explore.points} <= set(screen["sensor"])
    ranking = pd.read_csv(tmp / "adaptive" / "sensitivity.csv")
    assert set(ranking["fidelity"]) == {"screen"}


def test_a_second_run_resumes_without_computing_again(both):
    explore, _, adaptive, tmp = both
    again = Adaptive(explore, build_registry_with(explore), tmp / "adaptive").run()
    pd.testing.assert_frame_equal(again["min_spec"], adaptive["min_spec"])
    pd.testing.assert_frame_equal(again["refinement"], adaptive["refinement"])


def build_registry_with(explore):
    registry = build_registry()
    for point in explore.points:
        registry.add(point.spec)
    return registry


@pytest.mark.parametrize(
    ("sweep", "message"),
    [
        (
            '[sweep]\nbase = "adxl345"\ndesign = "lhs"\nsamples = 4\n[sweep.axes]\n'
            "sampling_rate_hz = { range = [800, 3200] }\n"
            "noise_density_ug_rthz = { range = [25, 1000] }\n"
            '[sweep.ties]\ndigital_cutoff_hz = "rate / 2 - 1"',
            "needs design = 'grid'",
        ),
        (
            '[sweep]\nbase = "adxl345"\n[sweep.axes]\nadc_bits = { levels = [8, 12] }\n'
            '[sweep.cost]\nadc_bits = { demand = "neither" }',
            "give its demand ('higher' or 'lower') in [sweep.cost.adc_bits]",
        ),
        (
            '[sweep]\nbase = "adxl345"\n[sweep.axes]\nadc_bits = { levels = [8, 12] }\n'
            "noise_density_ug_rthz = { levels = [90, 290] }",
            "is not one of its levels",
        ),
    ],
)
def test_adaptive_where_it_cannot_answer_is_one_line_before_any_work(
    sdt_in_process, tmp_path, sweep, message
):
    path = tmp_path / "sweep.toml"
    path.write_text(textwrap.dedent(sweep) + '\n[benchmark]\nmachines = ["Motor-2"]\n')
    out = tmp_path / "out"
    args = ["explore", str(path), "--strategy", "adaptive", "--quick", "--out", str(out)]
    result = sdt_in_process(*args)  # refused before any work: in this process
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --strategy adaptive"), lines
    assert message in lines[0] and "--strategy exhaustive" in lines[0]
    assert not out.exists()


def test_a_long_adaptive_sweep_needs_yes_before_its_design_is_built(
    sdt_main, tmp_path, monkeypatch
):
    """The screen runs every point, so it alone is costed and refused before the design exists."""

    def refuse(sweep):
        pytest.fail("the design was built before its size was checked")

    monkeypatch.setattr("sdt_framework.explore.run.design_points", refuse)
    monkeypatch.setattr("sdt_framework.bench.estimate.CONFIRM_ABOVE_SECONDS", 0.0)
    path = tmp_path / "sweep.toml"
    path.write_text(
        '[sweep]\nbase = "adxl345"\n[sweep.axes]\nnoise_density_ug_rthz = { levels = [90, 290] }\n'
        '[benchmark]\nmachines = ["Motor-2"]\n'
    )
    out = tmp_path / "out"
    code, _, err = sdt_main("explore", str(path), "--quick", "--out", str(out))
    assert code == 2 and err.count("\n") == 1 and not out.exists()
    # 2 points + reference and base, screened: 3 scenarios x 2 classifiers x 1 repetition
    assert err.startswith("error: this sweep of 2 design points (its screen alone) is 24 runs and ")
    assert "add --yes to run it" in err
