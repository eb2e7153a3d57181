"""Design matrices: which parameter combinations a sweep evaluates.

How each design samples is its entry in :data:`~sdt_framework.explore.designs.DESIGNS`:

- ``grid``: the full factorial of every axis's levels (a range gives ``steps``
  levels, evenly spaced on its scale).
- ``lhs``: a Latin hypercube of ``samples`` points (scipy.stats.qmc).
- ``sobol``: Saltelli's extension of a Sobol' sequence (SALib), the sample
  SALib's Sobol' analysis needs for first and total indices: ``samples * (d + 2)``
  points.
- ``morris``: ``samples`` elementary-effect trajectories on ``levels`` grid
  levels (SALib): ``samples * (d + 1)`` points.

Each design is first drawn in the unit cube (those coordinates are kept, the
sensitivity estimators need them) and then mapped to physical values: linear
or logarithmic within a range, or the nearest of an axis's explicit levels.
"""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd

from ..signals.sizes import building
from .designs import DESIGNS
from .size import design_size
from .sweep import INTEGER_FIELDS, Axis, Sweep, axis_levels

__all__ = ["design_points", "repeated_point", "unit_column"]


def unit_column(field: str) -> str:
    """Column holding a parameter's unit-cube coordinate."""
    return f"u_{field}"


def _to_value(axis: Axis, u: np.ndarray) -> np.ndarray:
    """Map unit coordinates to physical values on the axis."""
    if axis.levels is not None:
        levels = np.asarray(axis.levels, dtype=float)
        index = np.minimum((u * len(levels)).astype(int), len(levels) - 1)
        return levels[index]
    low, high = axis.range  # type: ignore[misc]
    if axis.scale == "log":
        return np.exp(np.log(low) + u * (np.log(high) - np.log(low)))
    return low + u * (high - low)


def design_points(sweep: Sweep) -> pd.DataFrame:
    """One row per design point: the swept fields in physical units (and ``u_`` columns).

    Integer fields (bits, filter order) are rounded to whole numbers. Rows keep
    the design's order (SALib's estimators rely on it). Should memory run out,
    the error names the design and its size (check sizes first:
    :func:`~sdt_framework.explore.size.design_size`).
    """
    what = f"building the {sweep.design} design of {design_size(sweep):,} points"
    with building(what, "use fewer levels, steps or samples"):
        return _design_points(sweep)


def _design_points(sweep: Sweep) -> pd.DataFrame:
    fields = list(sweep.axes)
    sample = DESIGNS[sweep.design].sample
    if sample is None:  # the full factorial of the axes' levels
        levels = [np.asarray(axis_levels(sweep.axes[f]), dtype=float) for f in fields]
        ranges = (range(len(values)) for values in levels)
        combos = np.array(list(itertools.product(*ranges)), dtype=np.intp).reshape(-1, len(fields))
        # by position, not by value: a level of NaN equals no level (it is skipped as a point)
        frame = pd.DataFrame({f: levels[i][combos[:, i]] for i, f in enumerate(fields)})
        for i, f in enumerate(fields):
            frame[unit_column(f)] = combos[:, i] / max(1, len(levels[i]) - 1)
    else:
        unit = sample(sweep)
        frame = pd.DataFrame(
            {f: _to_value(sweep.axes[f], unit[:, i]) for i, f in enumerate(fields)}
        )
        for i, f in enumerate(fields):
            frame[unit_column(f)] = unit[:, i]
    for f in fields:
        if f in INTEGER_FIELDS and np.isfinite(frame[f]).all():  # else: skipped as points
            frame[f] = frame[f].round().astype(int)
    frame.insert(0, "design_index", np.arange(len(frame)))
    return frame


def repeated_point(sweep: Sweep, design: pd.DataFrame) -> str | None:
    """Why two design points are one sensor (same values once mapped and rounded), or None.

    Two equal points would be one sensor under one name, which the benchmark
    cannot list twice; a design needs distinct points.
    """
    fields = list(sweep.axes)
    repeated = design.duplicated(fields, keep=False).to_numpy()
    if not repeated.any():
        return None
    first = design[repeated].iloc[0]
    same = design[repeated & (design[fields] == first[fields]).all(axis=1).to_numpy()]
    i, j = (int(k) for k in same["design_index"].iloc[:2])
    values = ", ".join(f"{f} = {first[f]:g}" for f in fields)
    rounded = [f for f in fields if f in INTEGER_FIELDS or sweep.axes[f].levels is not None]
    how = f" once mapped to {', '.join(rounded)}'s whole numbers or levels" if rounded else ""
    same_point = f"design points {i} and {j} are the same point ({values}){how}"
    if sweep.design == "grid":
        return f"{same_point}; give levels that stay distinct"
    advice = {"morris": "lower samples (its trajectories revisit the grid), or raise levels"}
    return (
        f"{same_point}: the {sweep.design} design with samples = {sweep.samples} repeats it; "
        f"{advice.get(sweep.design, 'change samples, or widen the ranges')}"
    )
