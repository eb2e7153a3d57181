"""Feature-space figure (paper Fig. 3): a 2-D t-SNE of standardised features per sensor.

The paper shows Motor-4 at defect severity level 1. Here, by default, the
first machine of the features table, the healthy windows plus, for each fault
class, the windows of its lowest severity level present (level 1 when the
data has it). Each sensor gets its own panel and its own embedding, computed
on that sensor's standardised features (zero mean, unit variance per feature).

A feature whose spread is rounding (constant, or within 1e-9 of its size, as
every feature of a DC-only recording is) carries nothing to embed and is left
out; a sensor with no other feature, or too few windows, gets a panel saying
so instead of an embedding (scikit-learn's t-SNE crashed the process,
segmentation fault and all, on identical points).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from .style import figure_label, new_figure

__all__ = ["FEATURE_META", "MIN_WINDOWS", "feature_columns", "lowest_severity", "plot_tsne"]

#: a feature whose standard deviation is at most this share of its largest magnitude
#: varies by rounding only: the float64 spread of a value computed from equal windows
CONSTANT_SPREAD = 1e-9
#: fewest windows a panel embeds (t-SNE needs its perplexity, at least 2, below the count)
MIN_WINDOWS = 5

#: leading columns of features.parquet that are not features
FEATURE_META = (
    "machine",
    "run",
    "condition",
    "severity",
    "channel",
    "recording_id",
    "sensor",
    "repeat",
    "acquisition",
    "window",
)


def feature_columns(features: pd.DataFrame) -> list[str]:
    """The numeric feature columns of a features table."""
    return [
        c
        for c in features.columns
        if c not in FEATURE_META and pd.api.types.is_numeric_dtype(features[c])
    ]


def lowest_severity(features: pd.DataFrame, machine: str | None = None) -> pd.DataFrame:
    """Windows of one machine: healthy (no severity) plus each fault's lowest severity level."""
    machine = machine or sorted(features["machine"].unique())[0]
    part = features[features["machine"] == machine]
    healthy = part[part["severity"].isna()]
    faults = part[part["severity"].notna()]
    lowest = faults.groupby("condition")["severity"].transform("min")
    return pd.concat([healthy, faults[faults["severity"] == lowest]], ignore_index=True)


def _varying(values: np.ndarray) -> np.ndarray:
    """Which columns vary by more than rounding (non-finite values counted as 0)."""
    finite = np.nan_to_num(values, nan=0.0, posinf=0.0, neginf=0.0)
    spread = finite.std(axis=0)
    return spread > CONSTANT_SPREAD * np.abs(finite).max(axis=0, initial=0.0)


def _embed(values: np.ndarray, seed: int) -> np.ndarray | str:
    """The 2-D t-SNE of ``values`` (windows x features), or why there is none."""
    from sklearn.manifold import TSNE
    from threadpoolctl import threadpool_limits

    if len(values) < MIN_WINDOWS:
        return f"{len(values)} windows: too few to embed"
    keep = _varying(values)
    if not keep.any():
        return f"no feature varies over the {len(values)} windows (constant or not finite)"
    finite = np.nan_to_num(values[:, keep], nan=0.0, posinf=0.0, neginf=0.0)
    scaled = (finite - finite.mean(axis=0)) / finite.std(axis=0)
    perplexity = float(min(30.0, max(2.0, (len(values) - 1) / 3)))
    tsne = TSNE(n_components=2, perplexity=perplexity, init="pca", random_state=seed)
    # one OpenMP thread: Barnes-Hut t-SNE slows down ~15x when threads contend for cores
    with threadpool_limits(limits=1, user_api="openmp"):
        return tsne.fit_transform(scaled)


def plot_tsne(
    features: pd.DataFrame,
    sensors: list[str],
    *,
    max_points: int = 1000,
    seed: int = 0,
    title: str = "",
) -> Figure:
    """One t-SNE panel per sensor, points coloured by class (condition).

    Parameters
    ----------
    features
        Feature rows (features.parquet layout), already restricted to the windows
        to show (see :func:`lowest_severity`).
    sensors
        Sensors to draw, one panel each, in order; sensors without rows are skipped.
    max_points
        At most this many windows per sensor (random subsample, fixed ``seed``),
        which keeps t-SNE to a few seconds per sensor.
    seed
        Random state of the subsample and of t-SNE.
    title
        Figure title.
    """
    columns = feature_columns(features)
    present = [s for s in sensors if s in set(features["sensor"])]
    classes = sorted(features["condition"].unique())
    cmap = _class_colors(len(classes))
    fig = new_figure(4.8 * max(len(present), 1) + 1.8, 4.8)
    axes = np.atleast_1d(fig.subplots(1, max(len(present), 1)))
    rng = np.random.default_rng(seed)
    for ax, sensor in zip(axes, present, strict=False):
        rows = features[features["sensor"] == sensor]
        if len(rows) > max_points:
            rows = rows.iloc[np.sort(rng.choice(len(rows), max_points, replace=False))]
        xy = _embed(rows[columns].to_numpy(dtype=np.float64), seed)
        ax.set(xlabel="t-SNE 1", ylabel="t-SNE 2", xticks=[], yticks=[])
        ax.set_title(f"{sensor} ({len(rows)} windows)", fontsize=10)
        if isinstance(xy, str):
            ax.text(0.5, 0.5, xy, ha="center", va="center", wrap=True, transform=ax.transAxes)
            continue
        for k, label in enumerate(classes):
            mask = (rows["condition"] == label).to_numpy()
            ax.scatter(
                xy[mask, 0],
                xy[mask, 1],
                s=9,
                color=cmap[k],
                label=figure_label(label),
                alpha=0.8,
                edgecolors="none",
            )
    drawn = [ax for ax in axes if ax.collections]
    handles, labels = drawn[0].get_legend_handles_labels() if drawn else ([], [])
    if handles:
        fig.legend(
            handles, labels, loc="outside right center", fontsize=8, title="class", markerscale=2
        )
    fig.suptitle(title or "t-SNE of standardised features", fontsize=11)
    return fig


def _class_colors(n: int) -> list[tuple[float, float, float, float]]:
    from matplotlib import colormaps

    cmap = colormaps["tab10" if n <= 10 else "tab20"]
    return [cmap(i % cmap.N) for i in range(n)]
