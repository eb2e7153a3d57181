"""Everything a sweep adds to its results folder, each file written atomically.

explore.parquet        one row per point x machine x scenario x classifier x repetition,
                       every swept parameter a column (reference/base rows included)
points.csv             every evaluated point: name, design index, values, cost, battery life
                       (the target's battery and report interval; NaN and why in life_note
                       where the sensor has no supply current on record)
skipped_points.csv     design points not evaluated (invalid, not finite, too fast), with reason
main_effects.csv       mean Macro-F1 per parameter level and cell, with 95 % CIs
sensitivity.csv        ANOVA shares (grid) or SALib indices (morris/sobol/lhs), ranked
min_spec.csv           least demanding level of each parameter meeting the target
min_spec_points.csv    every evaluated point meeting the target
pareto.csv             cost, mean Macro-F1 and battery life of every point, whether it
                       is on the cost/Macro-F1 front and on the front with battery life
                       (and its zone agreement, when the target asks for it)
(each analysis table has a ``fidelity`` column: "full" or "screen")
sweep.toml             the sweep as run (re-run or resume with ``sdt explore sweep.toml``)

The benchmark's own files (results.csv, table4.md, ...) sit beside them, so
``sdt report`` and ``sdt compare`` read a sweep folder like any benchmark's.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import tomli_w

from ..bench.config_paths import relative_to
from ..bench.folder import EXPLORE_FILES
from ..bench.results import write_frame
from ..edge.life_objective import non_dominated
from ..io import atomic_write_text
from .effects import CELL, main_effects, point_means, with_best
from .minspec import meeting_points, min_spec
from .pareto import demands, point_costs, with_front
from .run import ExplorePlan
from .sensitivity import sensitivity as ranking

__all__ = ["ANALYSES", "EXPLORE_FILES", "life_front", "write_explore", "write_sweep_file"]

#: the tables that answer a question, each with the fidelity it rests on
ANALYSES = ("main_effects", "sensitivity", "min_spec", "min_spec_points", "pareto")


def _base_cost(explore: ExplorePlan) -> float:
    if explore.sweep.base_cost is not None:
        return explore.sweep.base_cost
    price = getattr(explore.base, "price", None)
    return float(getattr(price, "value", price) or 0.0)


def _front_with_life(pareto: pd.DataFrame) -> pd.Series:
    """Per cell, the points no other beats on cost, Macro F1 and battery life together."""
    out = pd.Series(False, index=pareto.index)
    for _, part in pareto.groupby(CELL, sort=False):
        objectives = part[["cost", "macro_f1", "battery_life_years"]].to_numpy(float)
        out[part.index] = non_dominated(objectives * [1.0, -1.0, -1.0])
    return out


def life_front(pareto: pd.DataFrame) -> pd.DataFrame:
    """Per point, for the best classifier: cost, battery life, mean Macro F1, front membership.

    One row per point with a battery life, longest life first: its cost, its
    life (the target's battery and report interval), its Macro F1 averaged over the
    machine x scenario cells, and in how many of those cells it is on the
    front of cost, Macro F1 and battery life together (``on_front_with_life``
    of pareto.csv). Empty when no point has a life (no supply figures).
    """
    best = pareto[pareto["classifier"] == "best"]
    if best.empty:
        best = pareto
    best = best[np.isfinite(best["battery_life_years"].to_numpy(float))]
    columns = ["point", "cost", "battery_life_years", "macro_f1", "on_front", "cells"]
    if best.empty:
        return pd.DataFrame(columns=columns)
    grouped = best.groupby("point", sort=False)
    out = grouped.agg(
        cost=("cost", "first"),
        battery_life_years=("battery_life_years", "first"),
        macro_f1=("macro_f1", "mean"),
        on_front=("on_front_with_life", "sum"),
        cells=("on_front_with_life", "size"),
    ).reset_index()
    return out.sort_values(["battery_life_years", "cost"], ascending=[False, True])[columns]


def write_explore(
    explore: ExplorePlan,
    table: pd.DataFrame,
    out_dir: str | Path,
    fidelity: str = "full",
    sensitivity: pd.DataFrame | None = None,
    sweep_file: bool = True,
) -> dict[str, pd.DataFrame]:
    """Analyse the exploration table and write every file; return the tables by name.

    Every analysis table gets a ``fidelity`` column: "full" (the sweep's
    protocol) or "screen" (the adaptive strategy's cheap classifiers on one
    repetition). ``sensitivity``, when given, is written instead of the one
    computed here (the adaptive strategy's full-protocol points are not a
    balanced grid, so its ranking is the screen's, marked as such).
    ``sweep_file`` False leaves ``sweep.toml`` out (the adaptive strategy
    writes it once, at the top of its folder).
    """
    out = Path(out_dir)
    sweep = explore.sweep
    fields = list(sweep.axes)
    base_values = explore.base_values()
    demand = demands(sweep, explore.stage_axes)
    analysed = with_best(table)
    points = pd.DataFrame(
        [{"point": p.spec.name, "design_index": p.index, **p.values} for p in explore.points]
    )
    points["cost"] = point_costs(points, base_values, sweep, _base_cost(explore), demand)
    lives = explore.lives()  # NaN with the reason in life_note where no supply figure is on record
    points = points.merge(lives, on="point", how="left")
    means = point_means(analysed[analysed["role"] == "point"], fields)
    if "zone_agreement" in analysed:  # the target's second objective (explore.zones)
        shares = analysed.groupby(["point", "machine"])["zone_agreement"].first()
        means = means.join(shares, on=["point", "machine"])
    per_point = points[["point", "cost", "battery_life_years", "life_note"]]
    pareto = with_front(means.merge(per_point, on="point"))
    pareto["on_front_with_life"] = _front_with_life(pareto)
    tables = {
        "points": points,
        "skipped_points": explore.skipped,
        "main_effects": main_effects(analysed, fields),
        "sensitivity": (
            ranking(analysed, sweep, len(explore.design)) if sensitivity is None else sensitivity
        ),
        "min_spec": min_spec(analysed, fields, base_values, sweep.target, demand),
        "min_spec_points": meeting_points(analysed, fields, sweep.target),
        "pareto": pareto,
    }
    for name in ANALYSES:
        if "fidelity" not in tables[name]:
            tables[name].insert(len(tables[name].columns), "fidelity", fidelity)
    write_frame(table, out / "explore.parquet")
    for name, frame in tables.items():
        write_frame(frame, out / f"{name}.csv")
    if sweep_file:
        write_sweep_file(explore, out)
    return tables


def write_sweep_file(explore: ExplorePlan, out: Path) -> None:
    """``out/sweep.toml``: the sweep and its protocol as run, paths relative to ``out``."""
    sweep = explore.sweep
    atomic_write_text(
        out / "sweep.toml",
        "# The sweep as run by sdt explore; re-run or resume: sdt explore sweep.toml --out .\n"
        "# (paths are relative to this file's folder)\n"
        + tomli_w.dumps(
            {
                "sweep": sweep.model_dump(mode="json", exclude_none=True),
                "benchmark": relative_to(_protocol(explore), out),
            }
        ),
    )


def _protocol(explore: ExplorePlan) -> dict:
    data = explore.plan.config.model_dump(mode="json", exclude_none=True)
    data.pop("sensors", None)
    data.pop("cache_dir", None)  # this machine's cache, not the sweep (see bench.config)
    return data
