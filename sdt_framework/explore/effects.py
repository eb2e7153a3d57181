"""Main effects: mean Macro-F1 at each level of each swept parameter, with 95 % CIs.

Input everywhere in the analysis modules is the tidy exploration table: one
row per point x machine x scenario x classifier x repetition with columns
``point``, ``role`` ("reference", "base" or "point"), ``machine``,
``scenario``, ``classifier``, ``repeat``, ``macro_f1`` and one column per
swept parameter. These functions are pure: tables in, tables out.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd
from scipy import stats

__all__ = ["BEST", "CELL", "main_effects", "point_means", "with_best"]

#: pseudo-classifier: per point and cell, the classifier with the highest mean
BEST = "best"
#: the columns that identify one analysis cell
CELL = ["machine", "scenario", "classifier"]


def with_best(results: pd.DataFrame) -> pd.DataFrame:
    """``results`` plus rows for the best-of-classifiers pseudo-classifier ``"best"``.

    For each point, machine and scenario, the classifier with the highest mean
    Macro-F1 over repetitions is chosen (ties: the first by name) and its rows
    are repeated under ``classifier = "best"``.
    """
    keys = ["point", "machine", "scenario"]
    means = results.groupby([*keys, "classifier"], sort=True)["macro_f1"].mean().reset_index()
    winner = means.sort_values([*keys, "macro_f1"], ascending=[True] * 3 + [False])
    winner = winner.drop_duplicates(keys)[[*keys, "classifier"]]
    best = results.merge(winner, on=[*keys, "classifier"]).assign(classifier=BEST)
    return pd.concat([results, best[results.columns]], ignore_index=True)


def point_means(results: pd.DataFrame, fields: Sequence[str]) -> pd.DataFrame:
    """Mean and SD of Macro-F1 over repetitions, per point and cell."""
    keys = ["point", "role", *CELL]
    grouped = results.groupby(keys, sort=True, dropna=False)
    out = grouped["macro_f1"].agg(macro_f1="mean", sd="std", n="count").reset_index()
    params = results.drop_duplicates("point").set_index("point")[list(fields)]
    return out.join(params, on="point")


def _t_interval(values: np.ndarray) -> tuple[float, float]:
    if len(values) < 2:
        return float("nan"), float("nan")
    sem = stats.sem(values)
    if sem == 0:
        mean = float(np.mean(values))
        return mean, mean
    low, high = stats.t.interval(0.95, len(values) - 1, loc=np.mean(values), scale=sem)
    return float(low), float(high)


def main_effects(results: pd.DataFrame, fields: Sequence[str]) -> pd.DataFrame:
    """Mean Macro-F1 per level of each parameter, per cell, with a 95 % CI.

    The points at one level are averaged within each repetition first, so the
    interval (Student t over repetitions) reflects the noise draws and
    classifier seeds, not the spread between the other parameters' levels.
    Only design points enter (not the reference or the base).
    """
    points = results[results["role"] == "point"]
    rows: list[dict[str, object]] = []
    for field in fields:
        keys = [*CELL, field]
        per_repeat = points.groupby([*keys, "repeat"], sort=True)["macro_f1"].mean()
        for key, series in per_repeat.groupby(level=list(range(len(keys))), sort=True):
            values = series.to_numpy()
            low, high = _t_interval(values)
            rows.append(
                {
                    **dict(zip(CELL, key[:3], strict=True)),
                    "parameter": field,
                    "level": key[3],
                    "macro_f1": float(values.mean()),
                    "ci_low": low,
                    "ci_high": high,
                    "n_repeats": len(values),
                }
            )
    columns = [*CELL, "parameter", "level", "macro_f1", "ci_low", "ci_high", "n_repeats"]
    return pd.DataFrame(rows, columns=columns)
