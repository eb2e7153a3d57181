"""Design-space exploration: which sensor specification is enough for the faults at hand.

A sweep varies SensorSpec parameters and chain-stage parameters
(``"nonlinearity.second_pct_fs"``) around a base sensor (grid, Latin
hypercube, Sobol' or Morris designs), runs every point through the same
protocol as ``sdt benchmark``, and analyses the tidy results: main effects,
sensitivity ranking, minimum specification and the cost/Macro-F1 Pareto front.
This package uses :mod:`sdt_framework.bench`; nothing below it imports it.

Public API
----------
load_sweep(path) -> Sweep ; parse_sweep(data) ; plan_explore(sweep, protocol, overrides,
registry) -> ExplorePlan
    A sweep file read, and its design points planned through the benchmark's protocol.
sweep_estimate, exhaustive_estimate, assumptions ; estimates, not_adaptive, screen_of
    What a sweep costs before it runs, by strategy, and why the adaptive one cannot apply.
Adaptive(explore_plan, registry, out_dir)
    The adaptive strategy: a cheap screen of every point, then the full protocol where
    the minimum specification is decided.
explore_table(...) ; write_explore(...) ; life_front(pareto)
    The tidy results of a run, the analysis files written, the battery-life front.
main_effects, sensitivity, anova_shares, min_spec, meeting_points, pareto_front, ...
    The analyses on the tidy table.
"""

from __future__ import annotations

from .adaptive import Adaptive, estimates, not_adaptive, screen_of
from .design import design_points
from .effects import main_effects, point_means, with_best
from .minspec import meeting_points, min_spec
from .output import life_front, write_explore
from .pareto import pareto_front, point_costs
from .points import Point, build_points
from .run import ExplorePlan, explore_table, plan_explore
from .sensitivity import anova_shares, sensitivity
from .size import assumptions, exhaustive_estimate, sweep_estimate
from .stage_axes import check_stage_axes
from .sweep import Sweep
from .sweep_file import load_sweep, parse_sweep

__all__ = [
    "Adaptive",
    "ExplorePlan",
    "Point",
    "Sweep",
    "anova_shares",
    "assumptions",
    "build_points",
    "check_stage_axes",
    "design_points",
    "estimates",
    "exhaustive_estimate",
    "explore_table",
    "life_front",
    "load_sweep",
    "main_effects",
    "meeting_points",
    "min_spec",
    "not_adaptive",
    "pareto_front",
    "parse_sweep",
    "plan_explore",
    "point_costs",
    "point_means",
    "screen_of",
    "sensitivity",
    "sweep_estimate",
    "with_best",
    "write_explore",
]
