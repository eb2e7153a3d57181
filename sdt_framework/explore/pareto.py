"""Cost of a specification, and the cost/Macro-F1 Pareto front of the evaluated points.

Cost model (override per parameter in the sweep's ``[sweep.cost]`` table)::

    cost(point) = base_cost + sum over parameters  weight_p * steps_p

where ``steps_p`` counts how far the point's value moves from the base in the
parameter's demanding direction: ``log2(value / base)`` for a log-scale term
(one step = a doubling), ``value - base`` for a linear one, with the sign
flipped for parameters where lower is more demanding (noise density, error
terms; these count by magnitude ``|value|``). Moving towards an easier
specification lowers the cost. ``base_cost`` is the sweep's ``base_cost``,
else the base part's unit price when it has one, else 0. Defaults: weight 1
per doubling for every swept parameter, and 1 per bit or per filter order for
the integer ones. A stage parameter's default is 1 per halving of its
magnitude when its levels and base value are non-zero; else (an error term
swept from 0, or absent from the base, which counts as 0) it is linear, 1
cost unit across the tested span: weight 1 / (largest tested ``|level|``). A
parameter with no demanding direction (``"neither"``) costs nothing. The numbers are
relative effort, not money, unless the user writes prices into the terms.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from .effects import CELL
from .stage_axes import StageAxis, finite_or_zero, magnitude, stage_demand
from .sweep import DEMAND, INTEGER_FIELDS, CostTerm, Sweep, axis_levels, is_stage_key

__all__ = ["cost_terms", "demands", "pareto_front", "point_costs", "with_front"]


def demands(sweep: Sweep, stage_axes: Mapping[str, StageAxis] | None = None) -> dict[str, str]:
    """Demanding direction of every swept parameter: the sweep's override, else the default."""
    out = {}
    for field in sweep.axes:
        term = sweep.cost.get(field)
        axis = (stage_axes or {}).get(field)
        default = DEMAND.get(field) or (axis.demand if axis else stage_demand(field))
        out[field] = (term.demand if term else None) or default
    return out


def cost_terms(sweep: Sweep, base_values: Mapping[str, float] | None = None) -> dict[str, CostTerm]:
    """The cost term of every swept parameter (the sweep's, or the default)."""
    terms = {}
    for field in sweep.axes:
        default = CostTerm(scale="linear" if field in INTEGER_FIELDS else "log")
        if is_stage_key(field):
            base = abs(finite_or_zero(float((base_values or {}).get(field, 0.0))))
            magnitudes = [abs(v) for v in axis_levels(sweep.axes[field])]
            if not (base > 0 and min(magnitudes) > 0):  # 0 to the largest level: 1 unit
                default = CostTerm(scale="linear", weight=1.0 / (max(magnitudes) or 1.0))
        terms[field] = sweep.cost.get(field, default)
    return terms


def point_costs(
    values: pd.DataFrame,
    base_values: Mapping[str, float],
    sweep: Sweep,
    base_cost: float,
    demand: Mapping[str, str] | None = None,
) -> np.ndarray:
    """Cost of each row of ``values`` (one column per swept parameter)."""
    demand = demand or demands(sweep)
    total = np.full(len(values), float(base_cost))
    for field, term in cost_terms(sweep, base_values).items():
        direction = demand[field]
        if direction == "neither":
            continue
        base = float(base_values[field])
        base = finite_or_zero(base) if is_stage_key(field) else base
        value = magnitude(values[field].to_numpy(float), direction)
        base = float(magnitude(np.asarray(base), direction))
        steps = np.log2(value / base) if term.scale == "log" else value - base
        total += term.weight * (steps if direction == "higher" else -steps)
    return total


def pareto_front(cost: np.ndarray, score: np.ndarray) -> np.ndarray:
    """Mask of the non-dominated points: no other point is as cheap and as good, and better.

    A point is dominated when another costs no more and scores no less, and
    is strictly better in one of the two.
    """
    c, s = np.asarray(cost, float)[:, None], np.asarray(score, float)[:, None]
    no_worse = (c >= c.T) & (s <= s.T)
    better = (c > c.T) | (s < s.T)
    return ~(no_worse & better).any(axis=1)


def with_front(means: pd.DataFrame) -> pd.DataFrame:
    """``means`` (with ``cost`` and ``macro_f1`` columns) plus ``on_front`` per cell."""
    out = means.copy()
    out["on_front"] = False
    for _, part in out.groupby(CELL, sort=False):
        mask = pareto_front(part["cost"].to_numpy(), part["macro_f1"].to_numpy())
        out.loc[part.index, "on_front"] = mask
    return out
