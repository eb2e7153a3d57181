"""Cost of a specification, and the cost/Macro-F1 Pareto front of the evaluated points.

Cost model (override per parameter in the sweep's ``[sweep.cost]`` table)::

    cost(point) = base_cost + sum over parameters  weight_p * steps_p

where ``steps_p`` counts how far the point's value moves from the base in the
parameter's demanding direction: ``log2(value / base)`` for a log-scale term
(one step = a doubling), ``value - base`` for a linear one, with the sign
flipped for parameters where lower is more demanding (noise density). Moving
towards an easier specification lowers the cost. ``base_cost`` is the sweep's
``base_cost``, else the base part's unit price when it has one, else 0.
Defaults: weight 1 per doubling for every swept parameter, and 1 per bit or
per filter order for the integer ones. The numbers are relative effort, not
money, unless the user writes prices into the terms.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from .effects import CELL
from .sweep import DEMAND, INTEGER_FIELDS, CostTerm, Sweep

__all__ = ["cost_terms", "pareto_front", "point_costs", "with_front"]


def cost_terms(sweep: Sweep) -> dict[str, CostTerm]:
    """The cost term of every swept parameter (the sweep's, or the default)."""
    terms = {}
    for field in sweep.axes:
        default = CostTerm(scale="linear" if field in INTEGER_FIELDS else "log")
        terms[field] = sweep.cost.get(field, default)
    return terms


def point_costs(
    values: pd.DataFrame, base_values: Mapping[str, float], sweep: Sweep, base_cost: float
) -> np.ndarray:
    """Cost of each row of ``values`` (one column per swept parameter)."""
    total = np.full(len(values), float(base_cost))
    for field, term in cost_terms(sweep).items():
        value = values[field].to_numpy(float)
        base = float(base_values[field])
        steps = np.log2(value / base) if term.scale == "log" else value - base
        direction = term.demand or DEMAND[field]
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
