"""Minimum specification: the least demanding value of each parameter that still diagnoses.

For a target (an absolute Macro-F1, a fraction of the reference's, or a
largest loss to the reference) and each machine, scenario and classifier:

- per parameter, one at a time with every other swept parameter at the base
  sensor's value: the least demanding level L such that L and every more
  demanding level meet the target (so one lucky level in a noisy,
  non-monotone curve does not pass as a specification);
- every evaluated point that meets the target, whatever its other values.

"Demanding" is the direction in which a part is harder to make
(:data:`~sdt_framework.explore.sweep.DEMAND`, overridable in the cost model).
A point meets the target when its mean Macro-F1 over repetitions does.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from .effects import CELL, point_means
from .sweep import Target

__all__ = ["meeting_points", "min_spec", "thresholds"]


def thresholds(results: pd.DataFrame, target: Target) -> pd.Series:
    """Macro-F1 each cell must reach, indexed by (machine, scenario, classifier)."""
    cells = results.groupby(CELL, sort=True)["macro_f1"].size().index
    if target.macro_f1 is not None:
        return pd.Series(target.macro_f1, index=cells, name="threshold")
    reference = results[results["role"] == "reference"].groupby(CELL, sort=True)["macro_f1"].mean()
    reference = reference.reindex(cells)
    if target.fraction_of_reference is not None:
        return (reference * target.fraction_of_reference).rename("threshold")
    return (reference - target.max_loss).rename("threshold")


def _least_demanding(levels: np.ndarray, meets: np.ndarray, higher_is_harder: bool) -> float:
    order = np.argsort(levels)
    if not higher_is_harder:
        order = order[::-1]
    levels, meets = levels[order], meets[order]  # least demanding first
    # all more demanding levels meet: suffix-and of ``meets``
    robust = np.flip(np.logical_and.accumulate(np.flip(meets)))
    return float(levels[np.argmax(robust)]) if robust.any() else float("nan")


def min_spec(
    results: pd.DataFrame,
    fields: Sequence[str],
    base_values: Mapping[str, float],
    target: Target,
    demand: Mapping[str, str],
) -> pd.DataFrame:
    """One row per cell and parameter: the minimum level meeting the target (NaN if none)."""
    means = point_means(results[results["role"] == "point"], fields)
    limit = thresholds(results, target)
    rows: list[dict[str, object]] = []
    for cell, part in means.groupby(CELL, sort=True):
        threshold = float(limit.get(cell, np.nan))
        for field in fields:
            others = [f for f in fields if f != field]
            at_base = np.ones(len(part), dtype=bool)
            for other in others:
                at_base &= np.isclose(part[other].to_numpy(float), float(base_values[other]))
            line = part[at_base]
            note = "" if len(line) else "no evaluated point has the other parameters at the base"
            level = _least_demanding(
                line[field].to_numpy(float),
                line["macro_f1"].to_numpy() >= threshold,
                demand[field] == "higher",
            )
            if len(line) and np.isnan(level):
                note = "no level meets the target"
            rows.append(
                {
                    **dict(zip(CELL, cell, strict=True)),
                    "parameter": field,
                    "target": target.describe(),
                    "threshold": threshold,
                    "min_level": level,
                    "base_level": float(base_values[field]),
                    "levels_tested": len(line),
                    "note": note,
                }
            )
    columns = [*CELL, "parameter", "target", "threshold", "min_level", "base_level"]
    return pd.DataFrame(rows, columns=[*columns, "levels_tested", "note"])


def meeting_points(results: pd.DataFrame, fields: Sequence[str], target: Target) -> pd.DataFrame:
    """Every evaluated design point whose mean Macro-F1 meets the target, per cell."""
    means = point_means(results[results["role"] == "point"], fields)
    limit = thresholds(results, target)
    joined = means.join(limit, on=CELL)
    return joined[joined["macro_f1"] >= joined["threshold"]].reset_index(drop=True)
