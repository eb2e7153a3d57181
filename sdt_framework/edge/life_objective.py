"""Battery life as an objective beside Macro F1 and cost: what ``sdt explore`` calls.

:func:`point_lives` gives the node's battery life (years, :mod:`.node`) of each
design point's sensor, NaN where the sensor has no measuring current on record
(:func:`point_life` also says why). A swept profile keeps its base's supply
figures; a point whose rate differs from the base's keeps the base's measuring
current, which the datasheet gives per mode, so the life of such a point is
the base's current at the point's window and rate. :func:`non_dominated` is
the Pareto mask over any number of objectives to minimise (cost, -Macro F1,
-life).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from ..errors import SDTError
from ..specs import FeatureSetSpec, SensorSpec
from .cells import Cell, cell
from .node import NodeSettings, node_budget

__all__ = ["non_dominated", "point_life", "point_lives"]


def point_life(
    sensor: SensorSpec,
    feature_set: FeatureSetSpec,
    battery: Cell,
    settings: NodeSettings | None = None,
) -> tuple[float, str]:
    """Battery life in years and a note; or NaN and why it cannot be computed (never filled in).

    The note is ``""``, or, for a life the cell's shelf life caps, the cap's words.
    """
    supply = sensor.supply
    if supply is None:
        return math.nan, "no supply figures on record"
    if supply.measure_ua.value is None:
        return math.nan, f"no measuring supply current on record ({supply.measure_ua.cited()})"
    try:
        budget = node_budget(sensor, feature_set, battery, settings)
    except SDTError as exc:  # e.g. a report no uplink of the region carries
        return math.nan, str(exc)
    cap = f"capped at the {battery.name} cell's {battery.shelf_life_years:g}-year shelf life"
    return budget.life_years, cap if budget.life_capped else ""


def point_lives(
    sensors: Sequence[SensorSpec],
    feature_set: FeatureSetSpec,
    battery: Cell | str = "2xAA",
    settings: NodeSettings | None = None,
) -> np.ndarray:
    """Battery life in years per sensor; NaN where it cannot be computed (no supply figure)."""
    battery = battery if isinstance(battery, Cell) else cell(battery)
    return np.array([point_life(s, feature_set, battery, settings)[0] for s in sensors], float)


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
