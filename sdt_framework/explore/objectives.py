"""What a specification must reach, in one place: the target's threshold and each point's verdict.

Every answer that says "meets" or "fails" (the minimum specification, the
meeting points, the adaptive refinement's bisection) asks :func:`verdicts`,
and :func:`verdicts` asks :func:`thresholds`. An objective or constraint
added later is a field of :class:`~sdt_framework.explore.target.Target` plus
its entry in :data:`CONSTRAINTS` here (zone agreement, battery life): a column
of per-point values compared with a threshold, combined into ``meets``. Nothing
else in the package decides pass or fail.
"""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

from ..errors import SDTError
from .effects import CELL, point_means
from .target import Target

__all__ = [
    "CONSTRAINTS",
    "POINTWISE",
    "constraints",
    "diagnosis_meets",
    "thresholds",
    "verdicts",
]


def thresholds(results: pd.DataFrame, target: Target) -> pd.Series:
    """Macro-F1 each cell must reach, indexed by (machine, scenario, classifier)."""
    cells = results.groupby(CELL, sort=True)["macro_f1"].size().index
    if target.macro_f1 is not None:
        return pd.Series(target.macro_f1, index=cells, name="threshold")
    role = "base" if target.max_loss_to_base is not None else "reference"
    reference = results[results["role"] == role].groupby(CELL, sort=True)["macro_f1"].mean()
    reference = reference.reindex(cells)
    if target.max_loss_to_base is not None:
        return (reference - target.max_loss_to_base).rename("threshold")
    if target.fraction_of_reference is not None:
        return (reference * target.fraction_of_reference).rename("threshold")
    return (reference - target.max_loss).rename("threshold")


#: each constraint beside Macro F1: its name in ``meets_<name>``, the target's field,
#: the table's column of per-point values, what that value is per, and why it may be absent
CONSTRAINTS: dict[str, tuple[str, str, tuple[str, ...], str]] = {
    "zones": (
        "zone_agreement",
        "zone_agreement",
        ("point", "machine"),
        "features.parquet with V_RMS is missing",
    ),
    "life": (
        "min_battery_life_years",
        "battery_life_years",
        ("point",),
        "the table was built without the sweep's target",
    ),
}


#: constraints that are a fact of each point's design, not an estimate from noisy runs: the
#: minimum specification asks them of its chosen level only, not of every more demanding
#: one (a faster part drains the battery sooner: life falls as the demand rises)
POINTWISE = ("life",)


def constraints(target: Target) -> dict[str, float]:
    """The constraints ``target`` asks for beside Macro F1, by rule name, with their thresholds."""
    asked = {rule: getattr(target, field) for rule, (field, *_) in CONSTRAINTS.items()}
    return {rule: float(value) for rule, value in asked.items() if value is not None}


def verdicts(results: pd.DataFrame, fields: Sequence[str], target: Target) -> pd.DataFrame:
    """Per design point and cell: mean Macro-F1, the cell's threshold and ``meets``.

    A point meets the target when its mean over repetitions reaches the
    threshold (a cell without a threshold, NaN, is never met), and every
    constraint the target adds holds too:

    - ``zone_agreement``: its share of windows graded in the reference's ISO
      zone on that machine (the table's ``zone_agreement`` column, :mod:`.zones`);
    - ``min_battery_life_years``: its node's battery life (``battery_life_years``,
      :mod:`.life`); a point without one (no supply current on record) never meets it.

    With any constraint, ``meets_macro_f1`` and ``meets_zones`` / ``meets_life``
    say which holds, and ``meets`` is all of them.
    """
    means = point_means(results[results["role"] == "point"], fields)
    joined = means.join(thresholds(results, target), on=CELL)
    joined["meets"] = joined["macro_f1"] >= joined["threshold"]
    asked = constraints(target)
    if not asked:
        return joined
    joined["meets_macro_f1"] = joined["meets"]
    for rule, threshold in asked.items():
        field, column, per, why = CONSTRAINTS[rule]
        if column not in results.columns:
            raise SDTError(
                f"target.{field} needs each point's {column.replace('_', ' ')}, and these "
                f"results carry none ({why})"
            )
        values = results.groupby(list(per), sort=True)[column].first()
        joined = joined.join(values, on=list(per))
        joined[f"meets_{rule}"] = joined[column] >= threshold  # NaN (unknown) never meets
        joined["meets"] &= joined[f"meets_{rule}"]
    return joined


def diagnosis_meets(judged: pd.DataFrame) -> pd.Series:
    """``meets`` without the :data:`POINTWISE` constraints: what more demand can only help.

    The minimum specification's "every more demanding level meets too" and the
    adaptive strategy's bisection rest on this; battery life is asked of the
    chosen level alone (:mod:`.minspec`).
    """
    pointwise = [f"meets_{rule}" for rule in POINTWISE if f"meets_{rule}" in judged]
    if not pointwise:
        return judged["meets"]
    rules = [c for c in judged.columns if c.startswith("meets_") and c not in pointwise]
    return judged[rules].all(axis=1)
