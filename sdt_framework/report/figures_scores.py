"""Score figures: per-class radar charts (paper Fig. 6) and confusion matrices (Fig. 7).

Both take the long tables of a results folder (``per_class``, ``confusion``)
and return a matplotlib Figure; nothing here reads files.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from ..bench.results import scenario_rank, scenario_title
from .style import figure_label, new_figure

__all__ = ["best_class_f1", "plot_confusions", "plot_radar", "worst_cells"]


def best_class_f1(per_class: pd.DataFrame) -> pd.DataFrame:
    """Best per-class F1 over classifiers: mean over repeats first, then max over classifiers.

    Returns a frame with columns machine, scenario, sensor, class, f1.
    """
    keys = ["machine", "scenario", "sensor", "classifier", "class"]
    mean = per_class.groupby(keys, as_index=False)["f1"].mean()
    return mean.groupby(["machine", "scenario", "sensor", "class"], as_index=False)["f1"].max()


def plot_radar(per_class: pd.DataFrame, sensors: list[str], colors: dict[str, str]) -> Figure:
    """Radar charts of the best per-class F1: one per (machine, scenario).

    Rows are machines, columns scenarios (A, B, C, then speed-transfer arms); each
    chart has one axis per class of that machine and one closed polygon per sensor.
    Machines are kept apart because their class sets differ (paper Fig. 6 pools
    Motor-4 faults).
    """
    best = best_class_f1(per_class)
    machines = sorted(best["machine"].unique())
    scenarios = sorted(set(best["scenario"]), key=scenario_rank)
    fig = new_figure(4.6 * len(scenarios), 4.4 * len(machines) + 0.6)
    axes = fig.subplots(
        len(machines), len(scenarios), subplot_kw={"projection": "polar"}, squeeze=False
    )
    for i, machine in enumerate(machines):
        for j, scenario in enumerate(scenarios):
            ax = axes[i][j]
            part = best[(best["machine"] == machine) & (best["scenario"] == scenario)]
            classes = sorted(part["class"].unique())
            if len(classes) < 3:
                ax.set_axis_off()
                ax.set_title(f"{machine}\n{scenario_title(scenario)}\n(< 3 classes)", fontsize=9)
                continue
            angles = np.linspace(0, 2 * np.pi, len(classes), endpoint=False)
            closed = np.append(angles, angles[0])
            for sensor in [s for s in sensors if s in set(part["sensor"])]:
                f1 = part[part["sensor"] == sensor].set_index("class")["f1"].reindex(classes)
                values = np.append(f1.to_numpy(), f1.to_numpy()[0])
                label = figure_label(sensor)
                ax.plot(closed, values, color=colors.get(sensor), lw=1.6, label=label)
                ax.fill(closed, values, color=colors.get(sensor), alpha=0.08)
            names = [figure_label(c).replace(" ", "\n", 1) for c in classes]
            ax.set_xticks(angles, names, fontsize=7)
            ax.set_ylim(0, 1)
            ax.set_yticks([0.25, 0.5, 0.75, 1.0], ["0.25", "0.5", "0.75", "1"], fontsize=6)
            ax.set_title(f"{machine} — {scenario_title(scenario)}", fontsize=9, pad=14)
    handles, labels = axes[0][0].get_legend_handles_labels()
    if handles:
        fig.legend(handles, labels, loc="outside lower center", ncols=len(labels), fontsize=9)
    fig.suptitle("Best per-class F1 over classifiers (mean over repetitions)", fontsize=11)
    return fig


def worst_cells(results: pd.DataFrame, reference: str) -> pd.DataFrame:
    """Per machine, the non-reference (scenario, sensor, classifier) cell of lowest mean Macro F1.

    Falls back to the reference sensor for a machine that has no other sensor.
    """
    ok = results[results["status"] == "ok"]
    keys = ["machine", "scenario", "sensor", "classifier"]
    means = ok.groupby(keys, as_index=False)["macro_f1"].mean()
    picks = []
    for _, part in means.groupby("machine", sort=True):
        mems = part[part["sensor"] != reference]
        pool = mems if not mems.empty else part
        picks.append(pool.loc[pool["macro_f1"].idxmin()])
    return pd.DataFrame(picks, columns=[*keys, "macro_f1"]).reset_index(drop=True)


def plot_confusions(confusion: pd.DataFrame, cells: pd.DataFrame) -> Figure:
    """Row-normalised confusion matrices, summed over repetitions, one panel per cell.

    Parameters
    ----------
    confusion
        Long table (run columns, true, predicted, count).
    cells
        Rows with machine, scenario, sensor, classifier (and optionally macro_f1).
    """
    n = max(len(cells), 1)
    fig = new_figure(5.6 * n, 5.4)
    axes = np.atleast_1d(fig.subplots(1, n))
    image = None
    for ax, (_, cell) in zip(axes, cells.iterrows(), strict=False):
        keys = ["machine", "scenario", "sensor", "classifier"]
        mask = np.logical_and.reduce([confusion[k] == cell[k] for k in keys])
        counts = confusion[mask].pivot_table(
            index="true", columns="predicted", values="count", aggfunc="sum", fill_value=0
        )
        classes = sorted(set(counts.index) | set(counts.columns))
        counts = counts.reindex(index=classes, columns=classes, fill_value=0)
        totals = counts.sum(axis=1).replace(0, np.nan)
        share = counts.div(totals, axis=0).fillna(0.0).to_numpy()
        image = ax.imshow(share, cmap="Blues", vmin=0, vmax=1)
        for (r, c), value in np.ndenumerate(share):
            if value >= 0.005:
                ax.text(
                    c,
                    r,
                    f"{value:.2f}",
                    ha="center",
                    va="center",
                    fontsize=7,
                    color="white" if value > 0.6 else "black",
                )
        ticks = range(len(classes))
        names = [figure_label(c) for c in classes]
        ax.set_xticks(ticks, names, rotation=45, ha="right", fontsize=7)
        ax.set_yticks(ticks, names, fontsize=7)
        ax.set(xlabel="predicted class", ylabel="true class")
        score = f", macro F1 {cell['macro_f1']:.3f}" if "macro_f1" in cell else ""
        ax.set_title(
            f"{cell['machine']}, {scenario_title(cell['scenario'])}\n"
            f"{cell['sensor']} + "
            f"{str(cell['classifier']).upper()}{score}",
            fontsize=9,
        )
    if image is not None:
        fig.colorbar(image, ax=list(axes), shrink=0.7, label="share of true class")
    return fig
