"""Rows of the comparison table: one per cell, then per verdict group and overall.

A cell row summarises the paired differences of one cell over repetitions
and, when per-recording counts exist, the recording resamples of their mean.
A group row (e.g. one machine and scenario, all classifiers) averages its
cells: per repetition the mean difference over the cells (only repetitions
present in every cell), and per recording resample the mean of the cells'
resampled differences (the cells of one test set share the same draws).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd

from .recordings import RecordingSets

__all__ = ["aggregate_rows", "cell_rows"]

Draws = dict[tuple[str, tuple], np.ndarray | None]

ALL = "all"


def _summary(values: np.ndarray) -> dict[str, float]:
    n = len(values)
    return {
        "n_repeats": n,
        "delta": float(np.mean(values)) if n else np.nan,
        "sd": float(np.std(values, ddof=1)) if n > 1 else np.nan,
    }


def _interval(draws: np.ndarray | None, alpha: float) -> tuple[float, float]:
    if draws is None:
        return np.nan, np.nan
    low, high = np.quantile(draws, [alpha / 2, 1 - alpha / 2])
    return float(low), float(high)


def cell_rows(
    diffs: dict[str, pd.Series],
    wide: pd.DataFrame,
    baseline: str,
    cells: list[str],
    recordings: RecordingSets | None,
    treatment: str,
    alpha: float,
) -> tuple[list[dict[str, Any]], Draws]:
    """One row per (candidate, cell) and the recording resamples of each (None if absent)."""
    sides: dict[tuple, pd.DataFrame] = {}
    if recordings is not None:
        sides = dict(iter(recordings.frame.groupby([*cells, treatment], sort=False)))
    test_keys = recordings.group if recordings is not None else []
    rows: list[dict[str, Any]] = []
    draws: Draws = {}
    for candidate, diff in diffs.items():
        for cell, part in diff.groupby(level=cells, sort=True):
            cell = cell if isinstance(cell, tuple) else (cell,)
            repeats = sorted(part.index.get_level_values("repeat"))
            pairs = wide.loc[part.index, [candidate, baseline]]
            row = {"level": "cell", **dict(zip(cells, cell, strict=True))}
            row.update(baseline=baseline, candidate=candidate, **_summary(part.to_numpy()))
            row.update(
                baseline_mean=float(pairs[baseline].mean()),
                candidate_mean=float(pairs[candidate].mean()),
                n_cells=1,
                n_recordings=np.nan,
            )
            sample, detail = None, "no per-recording counts stored (per_recording.parquet)"
            if recordings is not None:
                key = tuple(row[k] for k in test_keys)
                empty = recordings.frame.iloc[:0]
                sample, detail = recordings.mean_difference(
                    sides.get((*cell, candidate), empty),
                    sides.get((*cell, baseline), empty),
                    key,
                    repeats,
                )
                test = recordings.test_set(key)
                if sample is not None and test is not None:
                    row["n_recordings"] = len(test.recordings)
                    detail = (
                        f"{len(test.recordings)} recordings, "
                        f"{test.smallest_class} in the smallest class"
                    )
            row["rec_ci_low"], row["rec_ci_high"] = _interval(sample, alpha)
            row["rec_detail"] = detail
            draws[(candidate, cell)] = sample
            rows.append(row)
    return rows, draws


def aggregate_rows(
    rows: list[dict[str, Any]],
    diffs: dict[str, pd.Series],
    draws: Draws,
    cells: list[str],
    groups: list[str],
    alpha: float,
) -> list[dict[str, Any]]:
    """Group rows (one per candidate and value of ``groups``) and overall rows."""
    frame = pd.DataFrame(rows)
    out: list[dict[str, Any]] = []
    levels = [("group", groups), ("overall", [])] if groups else [("overall", [])]
    for level, keys in levels:
        for candidate, diff in diffs.items():
            mine = frame[frame["candidate"] == candidate]
            parts = mine.groupby(keys, sort=True) if keys else [((), mine)]
            for key, part in parts:
                key = key if isinstance(key, tuple) else (key,)
                out.append(_aggregate(level, candidate, keys, key, part, diff, draws, cells, alpha))
    return out


def _aggregate(
    level: str,
    candidate: str,
    keys: Sequence[str],
    key: tuple,
    part: pd.DataFrame,
    diff: pd.Series,
    draws: Draws,
    cells: list[str],
    alpha: float,
) -> dict[str, Any]:
    members = [tuple(r) for r in part[cells].itertuples(index=False)]
    if len(cells) > 1:
        index = pd.MultiIndex.from_tuples(members, names=cells)
    else:
        index = pd.Index([m[0] for m in members], name=cells[0])
    by_repeat = diff.unstack("repeat").reindex(index)
    per_repeat = by_repeat.dropna(axis=1).mean(axis=0).to_numpy()
    row: dict[str, Any] = {"level": level, **{c: ALL for c in cells}}
    row.update(dict(zip(keys, key, strict=True)))
    row.update(baseline=part["baseline"].iloc[0], candidate=candidate, **_summary(per_repeat))
    row.update(
        baseline_mean=float(part["baseline_mean"].mean()),
        candidate_mean=float(part["candidate_mean"].mean()),
        n_cells=len(members),
    )
    samples = [draws.get((candidate, m)) for m in members]
    missing = sum(s is None for s in samples)
    sample = None if missing else np.mean(samples, axis=0)
    row["rec_ci_low"], row["rec_ci_high"] = _interval(sample, alpha)
    row["n_recordings"] = np.nan
    row["rec_detail"] = (
        f"recording CI missing for {missing} of {len(members)} cells"
        if missing
        else f"{len(members)} cells resampled together"
    )
    return row
