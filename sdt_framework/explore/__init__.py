"""Design-space exploration: which sensor specification is enough for the faults at hand.

A sweep varies SensorSpec parameters and chain-stage parameters
(``"nonlinearity.second_pct_fs"``) around a base sensor (grid, Latin
hypercube, Sobol' or Morris designs), runs every point through the same
protocol as ``sdt benchmark``, and analyses the tidy results: main effects,
sensitivity ranking, minimum specification and the cost/Macro-F1 Pareto front.
This package uses :mod:`sdt_framework.bench`; nothing below it imports it.
"""

from __future__ import annotations

from .design import design_points
from .effects import main_effects, point_means, with_best
from .minspec import meeting_points, min_spec
from .pareto import pareto_front, point_costs
from .points import Point, build_points
from .sensitivity import anova_shares, sensitivity
from .stage_axes import check_stage_axes
from .sweep import Sweep
from .sweep_file import load_sweep, parse_sweep

__all__ = [
    "Point",
    "Sweep",
    "anova_shares",
    "build_points",
    "check_stage_axes",
    "design_points",
    "load_sweep",
    "main_effects",
    "meeting_points",
    "min_spec",
    "pareto_front",
    "parse_sweep",
    "point_costs",
    "point_means",
    "sensitivity",
    "with_best",
]
