"""What a specification must reach, in one place: the target's threshold and each point's verdict.

Every answer that says "meets" or "fails" (the minimum specification, the
meeting points, the adaptive refinement's bisection) asks :func:`verdicts`,
and :func:`verdicts` asks :func:`thresholds`. An objective or constraint
added later (zone agreement, battery life) is a field of
:class:`~sdt_framework.explore.sweep.Target` plus its rule here: a column of
per-point values compared with a threshold, combined into ``meets``. Nothing
else in the package decides pass or fail.
"""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

from ..errors import SDTError
from .effects import CELL, point_means
from .sweep import Target

__all__ = ["thresholds", "verdicts"]


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


def verdicts(results: pd.DataFrame, fields: Sequence[str], target: Target) -> pd.DataFrame:
    """Per design point and cell: mean Macro-F1, the cell's threshold and ``meets``.

    A point meets the target when its mean over repetitions reaches the
    threshold (a cell without a threshold, NaN, is never met). With
    ``target.zone_agreement``, its share of windows graded in the reference's
    ISO zone on that machine (the table's ``zone_agreement`` column,
    :mod:`.zones`) must reach it too: ``meets_macro_f1`` and ``meets_zones``
    say which constraint holds, ``meets`` is both.
    """
    means = point_means(results[results["role"] == "point"], fields)
    joined = means.join(thresholds(results, target), on=CELL)
    joined["meets"] = joined["macro_f1"] >= joined["threshold"]
    if target.zone_agreement is None:
        return joined
    if "zone_agreement" not in results.columns:
        raise SDTError(
            "target.zone_agreement needs each point's zone agreement, and these results "
            "carry none (features.parquet with V_RMS is missing)"
        )
    shares = results.groupby(["point", "machine"], sort=True)["zone_agreement"].first()
    joined = joined.join(shares, on=["point", "machine"])
    joined["meets_macro_f1"] = joined["meets"]
    joined["meets_zones"] = joined["zone_agreement"] >= target.zone_agreement
    joined["meets"] = joined["meets_macro_f1"] & joined["meets_zones"]
    return joined
