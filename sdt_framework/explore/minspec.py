"""Minimum specification: the least demanding value of each parameter that still diagnoses.

For a target (an absolute Macro-F1, a fraction of the reference's, a largest
loss to the reference, or a largest loss to the base sensor: how much an
error term may cost) and each machine, scenario and classifier:

- per parameter, one at a time with every other swept parameter at the base
  sensor's value: the least demanding level L such that L and every more
  demanding level meet the target (so one lucky level in a noisy,
  non-monotone curve does not pass as a specification);
- every evaluated point that meets the target, whatever its other values.

"Demanding" is the direction in which a part is harder to make
(:data:`~sdt_framework.explore.sweep.DEMAND`, overridable in the cost model).
Where lower is harder (noise density, every error-term magnitude of a stage),
levels are ranked by their magnitude ``|value|`` and the answer is the largest
tolerable magnitude: a level meets only if every level of that magnitude
(``-x`` and ``+x``) and of every smaller one does. A parameter with no
demanding direction (``"neither"``, e.g. a correlation time) gets no level,
and a note saying why. A point meets the target when its mean Macro-F1 over
repetitions does (and, with ``zone_agreement`` or ``min_battery_life_years``,
each of those too; the level each constraint alone would allow is then given
beside, ``min_level_<rule>``, so the binding one is seen). Battery life is
asked of the chosen level only: more demand shortens it rather than making
it surer, so "every more demanding level too" would refuse every answer.
Pass or fail is :mod:`.objectives`'s.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd

from .effects import CELL
from .objectives import POINTWISE, constraints, diagnosis_meets, thresholds, verdicts
from .target import Target

__all__ = ["meeting_points", "min_spec", "thresholds"]


def _least_demanding(
    levels: np.ndarray, meets: np.ndarray, higher_is_harder: bool, holds: np.ndarray | None = None
) -> float:
    """The least demanding level that meets, with every more demanding level meeting too.

    ``holds`` (per row, e.g. battery life) is asked of the chosen level alone:
    a constraint that more demand does not help (:data:`.objectives.POINTWISE`).
    """
    if not higher_is_harder:
        levels = np.abs(levels)  # an error's magnitude: -x and +x are one specification
    unique, group = np.unique(levels, return_inverse=True)
    # a magnitude meets when every level of it does
    group_meets = np.bincount(group, weights=(~meets).astype(float), minlength=len(unique)) == 0
    held = np.ones(len(unique), dtype=bool)
    if holds is not None:
        held = np.bincount(group, weights=(~holds).astype(float), minlength=len(unique)) == 0
    if not higher_is_harder:  # least demanding first
        unique, group_meets, held = unique[::-1], group_meets[::-1], held[::-1]
    # all more demanding levels meet: suffix-and of ``group_meets``
    robust = np.flip(np.logical_and.accumulate(np.flip(group_meets))) & held
    return float(unique[np.argmax(robust)]) if robust.any() else float("nan")


def _no_line(others: Sequence[str], base_values: Mapping[str, float]) -> str:
    absent = [f for f in others if np.isnan(float(base_values[f]))]
    if absent:
        return (
            f"the base has no value of {', '.join(absent)} (a stage it does not list): "
            f"list the stage in the base profile at one of the levels"
        )
    return "no evaluated point has the other parameters at the base"


def min_spec(
    results: pd.DataFrame,
    fields: Sequence[str],
    base_values: Mapping[str, float],
    target: Target,
    demand: Mapping[str, str],
) -> pd.DataFrame:
    """One row per cell and parameter: the minimum level meeting the target (NaN if none)."""
    judged = verdicts(results, fields, target)
    rules = [] if not constraints(target) else ["macro_f1", *constraints(target)]
    rows: list[dict[str, object]] = []
    for cell, part in judged.groupby(CELL, sort=True):
        threshold = float(part["threshold"].iloc[0])
        for field in fields:
            others = [f for f in fields if f != field]
            at_base = np.ones(len(part), dtype=bool)
            for other in others:
                at_base &= np.isclose(part[other].to_numpy(float), float(base_values[other]))
            line = part[at_base]
            note = "" if len(line) else _no_line(others, base_values)
            by_rule: dict[str, float] = {}
            if demand[field] == "neither":
                level = float("nan")
                note = (
                    "no demanding direction (not an error magnitude): give its demand in "
                    "[sweep.cost] for a minimum level"
                )
            else:
                levels, harder = line[field].to_numpy(float), demand[field] == "higher"
                diagnosis = diagnosis_meets(line).to_numpy(bool)
                holds = line["meets_life"].to_numpy(bool) if "life" in rules else None
                level = _least_demanding(levels, diagnosis, harder, holds)
                for rule in rules:  # each constraint alone (zone agreement, battery life)
                    alone = line[f"meets_{rule}"].to_numpy(bool)
                    if rule in POINTWISE:
                        by_rule[rule] = _least_demanding(levels, alone | True, harder, alone)
                    else:
                        by_rule[rule] = _least_demanding(levels, alone, harder)
                if len(line) and np.isnan(level):
                    note = "no level meets the target"
                    if "life" in rules and line["battery_life_years"].isna().all():
                        note += (
                            ": these points have no battery life (points.csv, life_note, "
                            "says why), so the life constraint cannot be met"
                        )
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
                    **{f"min_level_{rule}": value for rule, value in by_rule.items()},
                }
            )
    columns = [*CELL, "parameter", "target", "threshold", "min_level", "base_level"]
    columns += ["levels_tested", "note"]
    columns += [f"min_level_{rule}" for rule in rules]  # each constraint alone, when several
    return pd.DataFrame(rows, columns=columns)


def meeting_points(results: pd.DataFrame, fields: Sequence[str], target: Target) -> pd.DataFrame:
    """Every evaluated design point that meets the target (every constraint of it), per cell."""
    judged = verdicts(results, fields, target)
    verdict = [c for c in judged.columns if c == "meets" or c.startswith("meets_")]
    return judged[judged["meets"]].drop(columns=verdict).reset_index(drop=True)
