"""The recording-level interval of the loss under a speed shift (issue 43).

Repetitions of a deterministic chain and classifier are identical, so the
interval over repetitions can be zero wide while the loss rests on a handful of
test recordings. The within-speed and shift arms of a fold are tested on the
same recordings, so the test set is resampled as the verdict resamples it
(:mod:`.recordings`: recordings drawn with replacement within each true class,
one draw shared by both arms and every sensor of the fold), Macro F1 recomputed
for both arms from the drawn recordings' confusion counts, and the 2.5 and 97.5
percentiles of the mean loss over repetitions give the interval.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .recordings import RecordingSets

__all__ = ["recording_intervals"]

#: the columns of a cell of the loss table the per-recording counts carry
CELL = ["machine", "sensor", "feature_set", "classifier"]


def recording_intervals(
    table: pd.DataFrame, per_recording: pd.DataFrame | None, n_boot: int = 2000, seed: int = 0
) -> pd.DataFrame:
    """``table`` (:func:`.speed_loss.speed_loss`) with ``rec_low``, ``rec_high`` (NaN where none)
    and ``rec_note``, why there is none (no counts stored, one test recording in a class...)."""
    table = table.assign(rec_low=np.nan, rec_high=np.nan, rec_note="")
    if per_recording is None or per_recording.empty or table.empty:
        return table.assign(rec_note="no per-recording counts stored (per_recording.parquet)")
    arms = dict(zip(table["shift"], table["within"], strict=False))
    fold = {**{s: s for s in arms}, **{w: s for s, w in arms.items()}}
    rows = per_recording[per_recording["scenario"].isin(fold)]
    rows = rows.assign(_fold=rows["scenario"].map(fold))
    sets = RecordingSets(rows, ["machine", "_fold"], n_boot=n_boot, seed=seed)
    coded = sets.frame
    keys = [c for c in CELL if c in coded.columns]
    groups = {k: g for k, g in coded.groupby([*keys, "scenario"], sort=False, dropna=False)}
    for index, row in table.iterrows():
        cell = tuple(row[k] for k in keys)
        within, shift = groups.get((*cell, row["within"])), groups.get((*cell, row["shift"]))
        if within is None or shift is None:
            table.loc[index, "rec_note"] = "no per-recording counts stored for this cell"
            continue
        repeats = sorted(set(within["repeat"]) & set(shift["repeat"]))
        draws, why = sets.mean_difference(within, shift, (row["machine"], row["shift"]), repeats)
        if draws is None:
            table.loc[index, "rec_note"] = why
            continue
        table.loc[index, ["rec_low", "rec_high"]] = np.percentile(draws, [2.5, 97.5])
    return table
