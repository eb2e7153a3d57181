"""Battery life as an objective beside Macro F1 and cost: what ``sdt explore`` calls.

:func:`point_lives` gives the node's battery life (years, :mod:`.node`) of each
design point's sensor, NaN where the sensor has no measuring current on
record (a swept profile keeps its base's supply figures; a point whose rate
differs from the base's keeps the base's measuring current, which the
datasheet gives per mode, so the life of such a point is the base's current at
the point's window and rate). :func:`non_dominated` is the Pareto mask over
any number of objectives to minimise (cost, -Macro F1, -life).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from ..errors import SDTError
from ..specs import FeatureSetSpec, SensorSpec
from .cells import Cell, cell
from .node import NodeSettings, battery_life_years

__all__ = ["non_dominated", "point_lives"]


def point_lives(
    sensors: Sequence[SensorSpec],
    feature_set: FeatureSetSpec,
    battery: Cell | str = "2xAA",
    settings: NodeSettings | None = None,
) -> np.ndarray:
    """Battery life in years per sensor; NaN where it cannot be computed (no supply figure)."""
    battery = battery if isinstance(battery, Cell) else cell(battery)
    out = np.full(len(sensors), np.nan)
    for i, sensor in enumerate(sensors):
        try:
            years = battery_life_years(sensor, feature_set, battery, settings)
        except SDTError:  # e.g. an interval too short for this point's window
            years = None
        if years is not None:
            out[i] = years
    return out


def non_dominated(minimise: np.ndarray) -> np.ndarray:
    """Mask of the rows no other row dominates (no worse in every column, better in one).

    ``minimise`` is (points, objectives), each column to be minimised; a row
    with a NaN objective is never on the front and dominates nothing.
    """
    values = np.asarray(minimise, float)
    if values.ndim != 2:
        raise SDTError(f"objectives must be a (points, objectives) array, got shape {values.shape}")
    finite = np.isfinite(values).all(axis=1)
    a, b = values[:, None, :], values[None, :, :]
    dominated_by = (b <= a).all(axis=2) & (b < a).any(axis=2) & finite[None, :]
    return finite & ~dominated_by.any(axis=1)
