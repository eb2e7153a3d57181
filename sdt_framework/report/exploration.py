"""The report's "Exploration" section, for results folders written by ``sdt explore``.

It reads the sweep's analysis tables (points, main effects, sensitivity,
minimum specification, Pareto front) from the folder and draws four figures:
main-effect panels, a Macro-F1 heatmap over the two most influential
parameters, the sensitivity ranking with its CIs, and the cost/F1 plot. All
show the best-of-classifiers pseudo-classifier ("best"); the CSV files hold
every classifier.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from ..csv_cells import unescape_frame
from ..explore.designs import DESIGNS
from .document import Block, Figure, Heading, Paragraph, Table, literal
from .style import figure_label, new_figure, save_figure

__all__ = ["exploration_blocks"]

BEST = "best"
_TABLES = ("points", "main_effects", "sensitivity", "min_spec", "pareto")


def _read(folder: Path) -> dict[str, pd.DataFrame] | None:
    if not (folder / "points.csv").exists():
        return None
    tables = {}
    for name in _TABLES:
        try:
            tables[name] = unescape_frame(pd.read_csv(folder / f"{name}.csv"))
        except (OSError, ValueError, pd.errors.EmptyDataError):
            tables[name] = pd.DataFrame()
    return tables


def _ranking(sens: pd.DataFrame) -> pd.DataFrame:
    best = sens[(sens["classifier"] == BEST) & sens["term"].notna()]
    first = {design.method: design.headline for design in DESIGNS.values()}
    best = best[best["index"] == best["method"].map(first)]
    return best[~best["term"].astype(str).str.contains(":|residual")]


def _fig_effects(effects: pd.DataFrame, out: Path) -> Path:
    best = effects[effects["classifier"] == BEST]
    params = list(dict.fromkeys(best["parameter"]))
    fig = new_figure(3.2 * len(params), 3.0)
    axes = np.atleast_1d(fig.subplots(1, len(params), sharey=True))
    for ax, param in zip(axes, params, strict=True):
        for (machine, scenario), line in best[best["parameter"] == param].groupby(
            ["machine", "scenario"]
        ):
            line = line.sort_values("level")
            err = np.vstack([line["macro_f1"] - line["ci_low"], line["ci_high"] - line["macro_f1"]])
            ax.errorbar(
                line["level"],
                line["macro_f1"],
                yerr=np.nan_to_num(err),
                marker="o",
                capsize=2,
                label=f"{machine} / {scenario}",
            )
        levels = np.sort(best.loc[best["parameter"] == param, "level"].unique())
        positive = levels[levels > 0]
        if levels.min() > 0 and levels.max() / levels.min() >= 8:
            ax.set_xscale("log")
            ax.minorticks_off()
        elif levels.min() == 0 and len(positive) >= 2 and positive[-1] / positive[0] >= 8:
            ax.set_xscale("symlog", linthresh=positive[0])  # an error term swept from 0
            ax.minorticks_off()
        if len(levels) <= 8:
            ax.set_xticks(levels, [f"{v:g}" for v in levels])
        ax.set_xlabel(param)
    axes[0].set_ylabel("Macro-F1 (best classifier)")
    axes[-1].legend(fontsize=7)
    return save_figure(fig, out, "explore_main_effects.png")


def _fig_heatmap(pareto: pd.DataFrame, pair: list[str], out: Path) -> Path:
    best = pareto[pareto["classifier"] == BEST]
    grid = best.pivot_table(index=pair[0], columns=pair[1], values="macro_f1", aggfunc="mean")
    fig = new_figure(5.0, 4.0)
    ax = fig.subplots()
    image = ax.imshow(grid.to_numpy(), origin="lower", aspect="auto", cmap="viridis")
    ax.set_xticks(range(grid.shape[1]), [f"{v:g}" for v in grid.columns], rotation=45)
    ax.set_yticks(range(grid.shape[0]), [f"{v:g}" for v in grid.index])
    ax.set_xlabel(pair[1])
    ax.set_ylabel(pair[0])
    fig.colorbar(image, ax=ax, label="mean Macro-F1 (best classifier)")
    return save_figure(fig, out, "explore_heatmap.png")


def _fig_sensitivity(ranking: pd.DataFrame, out: Path) -> Path:
    cells = list(dict.fromkeys(zip(ranking["machine"], ranking["scenario"], strict=True)))
    terms = list(dict.fromkeys(ranking["term"]))
    fig = new_figure(max(4.0, 1.2 * len(terms) * max(1, len(cells)) / 2), 3.2)
    ax = fig.subplots()
    width = 0.8 / max(1, len(cells))
    for i, cell in enumerate(cells):
        part = ranking[(ranking["machine"] == cell[0]) & (ranking["scenario"] == cell[1])]
        part = part.set_index("term").reindex(terms)
        x = np.arange(len(terms)) + i * width
        ax.bar(x, part["value"], width, label=f"{cell[0]} / {cell[1]}")
        ax.vlines(x, part["ci_low"], part["ci_high"], color="black", linewidth=1)  # 95 % CI
    names = [figure_label(term) for term in terms]
    ax.set_xticks(np.arange(len(terms)) + 0.4 - width / 2, names, rotation=20)
    ax.set_ylabel(str(ranking["index"].iloc[0]))
    ax.legend(fontsize=7)
    return save_figure(fig, out, "explore_sensitivity.png")


def _fig_pareto(pareto: pd.DataFrame, out: Path) -> Path:
    best = pareto[pareto["classifier"] == BEST]
    fig = new_figure(5.5, 3.8)
    ax = fig.subplots()
    for (machine, scenario), part in best.groupby(["machine", "scenario"]):
        dots = ax.scatter(part["cost"], part["macro_f1"], s=12, alpha=0.5)
        front = part[part["on_front"]].sort_values("cost")
        ax.step(
            front["cost"],
            front["macro_f1"],
            where="post",
            color=dots.get_facecolor()[0],
            label=f"{machine} / {scenario}",
        )
    ax.set_xlabel("cost (sweep cost model)")
    ax.set_ylabel("mean Macro-F1 (best classifier)")
    ax.legend(fontsize=7)
    return save_figure(fig, out, "explore_pareto.png")


def _min_spec_table(min_spec: pd.DataFrame) -> Table:
    best = min_spec[min_spec["classifier"] == BEST]
    rows = tuple(
        (
            literal(r.machine),
            literal(r.scenario),
            literal(r.parameter),
            f"{r.threshold:.3f}",
            "none" if pd.isna(r.min_level) else f"{r.min_level:g}",
            "absent" if pd.isna(r.base_level) else f"{r.base_level:g}",
        )
        for r in best.itertuples()
    )
    return Table(("machine", "scenario", "parameter", "F1 needed", "minimum level", "base"), rows)


def exploration_blocks(folder: Path, figures: Path) -> list[Block]:
    """The section's blocks, or nothing when ``folder`` holds no sweep; figures go to
    ``figures`` (the report's figures folder, which may be elsewhere: ``--out``)."""
    tables = _read(folder)
    if tables is None:
        return []
    blocks: list[Block] = [
        Heading("Exploration", 2),
        Paragraph(
            f"{len(tables['points'])} design points evaluated (see points.csv, "
            f"skipped_points.csv). Figures show the best classifier per point and cell."
        ),
    ]
    ranking = _ranking(tables["sensitivity"])
    if not tables["min_spec"].empty:
        target = tables["min_spec"]["target"].iloc[0]
        blocks += [
            Heading(f"Minimum specification ({literal(target)})", 3),
            _min_spec_table(tables["min_spec"]),
        ]
    drawn = []
    if not tables["main_effects"].empty:
        drawn.append(
            (
                _fig_effects(tables["main_effects"], figures),
                "Main effects: mean Macro-F1 per level with 95 % CIs over repetitions.",
            )
        )
    if not ranking.empty:
        drawn.append((_fig_sensitivity(ranking, figures), "Sensitivity ranking with CIs."))
        order = ranking.groupby("term")["value"].mean().sort_values(ascending=False)
        if len(order) >= 2 and not tables["pareto"].empty:
            drawn.append(
                (
                    _fig_heatmap(tables["pareto"], list(order.index[:2]), figures),
                    f"Mean Macro-F1 over {literal(order.index[0])} and {literal(order.index[1])}, "
                    f"the two most influential parameters.",
                )
            )
    if not tables["pareto"].empty:
        drawn.append(
            (
                _fig_pareto(tables["pareto"], figures),
                "Cost against mean Macro-F1; the line joins the Pareto front.",
            )
        )
    blocks += [Figure(path, caption) for path, caption in drawn]
    return blocks
