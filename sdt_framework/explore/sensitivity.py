"""Sensitivity ranking: which chain parameter moves Macro-F1, and by how much.

- grid designs: the classical ANOVA decomposition of a balanced full
  factorial. With ``y`` every run's Macro-F1, the share of a main effect A is
  ``SS_A / SS_total`` with ``SS_A = sum over runs (mean_A(level) - mean)^2``, and
  of a two-way interaction ``SS_AB = sum (mean_AB - mean_A - mean_B + mean)^2``;
  what is left (higher interactions and repetition noise) is the residual.
  95 % CIs come from a bootstrap over repetitions (resampled jointly across
  points, as the points share noise draws).
- morris: SALib's elementary effects (mu*, sigma) with mu*'s CI;
- sobol: SALib's first-order and total indices (S1, ST) with their CIs;
- lhs: SALib's delta moment-independent measure (Plischke's raw estimator) and
  S1, with CIs.

Which estimator a design gets is its entry in
:data:`~sdt_framework.explore.designs.DESIGNS`. The SALib estimators need the
whole design: if a point was skipped, the cell gets a row saying so instead of
numbers.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

import numpy as np
import pandas as pd

from ..seeding import rng
from .design import unit_column
from .designs import DESIGNS
from .effects import CELL
from .sweep import Sweep

__all__ = ["anova_shares", "sensitivity"]

BOOTSTRAP = 200
COLUMNS = [*CELL, "method", "term", "index", "value", "ci_low", "ci_high", "note"]


def anova_shares(codes: dict[str, np.ndarray], y: np.ndarray) -> dict[str, float]:
    """Variance shares of main effects, two-way interactions and the residual.

    ``codes[field]`` is each point's level index; ``y`` is (points, repetitions).
    """
    grand = y.mean()
    total = ((y - grand) ** 2).sum()
    if total == 0:
        return {}
    m = y.mean(axis=1)
    reps = y.shape[1]
    level_means = {}
    shares: dict[str, float] = {}
    for field, code in codes.items():
        means = np.bincount(code, weights=m) / np.bincount(code)
        level_means[field] = means[code]
        shares[field] = reps * ((level_means[field] - grand) ** 2).sum() / total
    for a, b in itertools.combinations(codes, 2):
        cell = codes[a] * (codes[b].max() + 1) + codes[b]
        _, inverse = np.unique(cell, return_inverse=True)
        cell_means = (np.bincount(inverse, weights=m) / np.bincount(inverse))[inverse]
        resid = cell_means - level_means[a] - level_means[b] + grand
        shares[f"{a}:{b}"] = reps * (resid**2).sum() / total
    shares["residual"] = 1.0 - sum(shares.values())
    return shares


def _grid_rows(cell: tuple, part: pd.DataFrame, fields: Sequence[str]) -> list[dict]:
    y = part.pivot_table(index="point", columns="repeat", values="macro_f1").sort_index()
    params = part.drop_duplicates("point").set_index("point").loc[y.index]
    codes = {f: np.unique(params[f].to_numpy(), return_inverse=True)[1] for f in fields}
    values = y.to_numpy()
    shares = anova_shares(codes, values)
    base = dict(zip(CELL, cell, strict=True))
    if not shares:
        return [{**base, "method": "anova", "note": "Macro-F1 does not vary across the grid"}]
    generator = rng(0, "anova-bootstrap", *cell)
    draws = {term: [] for term in shares}
    for _ in range(BOOTSTRAP):
        sample = values[:, generator.integers(0, values.shape[1], values.shape[1])]
        for term, share in anova_shares(codes, sample).items():
            draws[term].append(share)
    rows = []
    for term, share in shares.items():
        low, high = np.percentile(draws[term], [2.5, 97.5]) if draws[term] else (np.nan,) * 2
        rows.append(
            {
                **base,
                "method": "anova",
                "term": term,
                "index": "share",
                "value": share,
                "ci_low": float(low),
                "ci_high": float(high),
                "note": "",
            }
        )
    return rows


def _salib_rows(cell: tuple, part: pd.DataFrame, sweep: Sweep, n_design: int) -> list[dict]:
    base = dict(zip(CELL, cell, strict=True))
    means = part.groupby("design_index")["macro_f1"].mean()
    if len(means) != n_design:
        note = f"{n_design - len(means)} of {n_design} design points were skipped; SALib needs all"
        return [{**base, "method": DESIGNS[sweep.design].method, "note": note}]
    y = means.sort_index().to_numpy()
    units = part.drop_duplicates("design_index").sort_values("design_index")
    x = units[[unit_column(f) for f in sweep.axes]].to_numpy()
    design = DESIGNS[sweep.design]
    res = design.analyse(sweep, x, y)  # type: ignore[misc]
    indices = design.indices or {}
    notes = res.get("notes")  # SALib's own per-parameter notes (delta), kept in the table
    rows = []
    for i, field in enumerate(sweep.axes):
        note = str(notes[i]).strip() if notes is not None and len(notes) > i else ""
        for index, conf in indices.items():
            value = float(res[index][i])
            half = float(res[conf][i]) if conf else float("nan")
            rows.append(
                {
                    **base,
                    "method": DESIGNS[sweep.design].method,
                    "term": field,
                    "index": index,
                    "value": value,
                    "ci_low": value - half,
                    "ci_high": value + half,
                    "note": note,
                }
            )
    return rows


def sensitivity(results: pd.DataFrame, sweep: Sweep, n_design: int) -> pd.DataFrame:
    """The sensitivity table of every cell (design points only), ranked within each cell."""
    points = results[results["role"] == "point"]
    fields = list(sweep.axes)
    rows: list[dict] = []
    for cell, part in points.groupby(CELL, sort=True):
        if DESIGNS[sweep.design].analyse is None:  # the ANOVA of a full factorial
            rows.extend(_grid_rows(cell, part, fields))
        else:
            rows.extend(_salib_rows(cell, part, sweep, n_design))
    table = pd.DataFrame(rows, columns=COLUMNS)
    table["rank"] = (
        table[table["term"] != "residual"]
        .groupby([*CELL, "index"])["value"]
        .rank(ascending=False, method="min")
    )
    return table
