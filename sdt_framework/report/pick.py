"""Which recording, and which channel of it, the signal figure (Fig. 2) shows.

The condition: as in the paper when the data has it, the highest level of
"cavitation suction" (the paper's Motor-4 cavitation suction 4), else of any
condition containing "cavitation", else of any fault.

The channel: the one that shows the condition. A campaign's channels are named
by its DAQ (``acc-ai0`` ... ``acc-ai3`` of an NI 9234), not ``ch1``, and its
first channel may sit where the condition barely reaches (issue 40: the first
channel of a cavitation test, on the motor, showed no cavitation). The rule:
per channel of the chosen run, the reference sensor's windows of that
condition and level (every test of it) against the healthy windows of the
same machine and channel, and for each feature the distance of their means in
pooled standard deviations, |m_c - m_h| / sqrt((s_c^2 + s_h^2) / 2); the
channel with the largest distance over all features is shown, and the caption
names the feature and the runner-up. Without features.parquet, or without
healthy windows to compare with, ``ch1`` when present, else the first channel
by name, and the caption says so.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..data.recording import Recording
from ..errors import SDTError
from .figures_features import feature_columns

__all__ = ["Choice", "channel_contrast", "pick_recording"]

#: fewest windows on each side for a channel's distance to count
MIN_WINDOWS = 2


@dataclass(frozen=True)
class Choice:
    """The recording a signal figure shows, and why that channel."""

    recording: Recording
    reason: str


def channel_contrast(
    features: pd.DataFrame,
    reference: str,
    machine: str,
    condition: str,
    severity: float | None,
) -> pd.DataFrame:
    """Per channel: the feature that best separates the condition from healthy, and by how much.

    Columns ``channel``, ``feature``, ``distance`` (pooled standard deviations),
    sorted from the largest distance; a channel without :data:`MIN_WINDOWS`
    windows on either side, or whose features do not vary, is left out.
    """
    rows = features[(features["sensor"] == reference) & (features["machine"] == machine)]
    if "repeat" in rows and len(rows):
        rows = rows[rows["repeat"] == rows["repeat"].min()]
    columns = feature_columns(rows)
    healthy = rows["severity"].isna() & (rows["condition"] != condition)
    level = rows["severity"].isna() if severity is None else rows["severity"] == severity
    fault = (rows["condition"] == condition) & level
    out = []
    for channel, part in rows.groupby("channel", sort=True):
        h = part.loc[healthy[part.index], columns].to_numpy(float)
        c = part.loc[fault[part.index], columns].to_numpy(float)
        if len(h) < MIN_WINDOWS or len(c) < MIN_WINDOWS:
            continue
        with np.errstate(divide="ignore", invalid="ignore"):
            pooled = np.sqrt((h.var(axis=0, ddof=1) + c.var(axis=0, ddof=1)) / 2)
            distance = np.abs(c.mean(axis=0) - h.mean(axis=0)) / pooled
        distance[~np.isfinite(distance)] = np.nan
        if np.all(np.isnan(distance)):
            continue
        best = int(np.nanargmax(distance))
        out.append((str(channel), columns[best], float(distance[best])))
    table = pd.DataFrame(out, columns=["channel", "feature", "distance"])
    return table.sort_values(["distance", "channel"], ascending=[False, True], ignore_index=True)


def _by_name(pool: list[Recording]) -> str:
    return "ch1" if any(r.channel == "ch1" for r in pool) else min(r.channel for r in pool)


def pick_recording(
    recordings: list[Recording],
    features: pd.DataFrame | None = None,
    reference: str | None = None,
) -> Choice:
    """The recording for Fig. 2: the condition as in the paper, the channel that shows it."""
    if not recordings:
        raise SDTError("the dataset has no recordings to draw")
    for test in (
        lambda r: r.condition == "cavitation suction",
        lambda r: "cavitation" in r.condition,
        lambda r: r.severity is not None,
    ):
        pool = [r for r in recordings if test(r)]
        if pool:
            break
    else:
        return Choice(recordings[0], "no fault in the data: the first recording")
    top = max(pool, key=lambda r: (r.severity or 0, r.machine, r.run))
    run = [r for r in pool if (r.machine, r.run) == (top.machine, top.run)]
    channels = {r.channel: r for r in run}
    contrast = pd.DataFrame()
    if features is not None and reference is not None and len(features):
        contrast = channel_contrast(features, reference, top.machine, top.condition, top.severity)
        contrast = contrast[contrast["channel"].isin(list(channels))]
    if contrast.empty:
        channel = _by_name(run)
        why = "no healthy and fault windows of the reference in features.parquet to compare"
        return Choice(channels[channel], f"{channel} by name ({why})")
    best = contrast.iloc[0]
    level = f"{top.condition} {top.severity:g}" if top.severity is not None else top.condition
    reason = (
        f"{best.channel}, where {level} differs most from healthy: feature {best.feature} "
        f"{best.distance:.1f} pooled SDs apart (reference windows, every test of the level)"
    )
    if len(contrast) > 1:
        second = contrast.iloc[1]
        reason += f"; next {second.channel} ({second.feature}, {second.distance:.1f})"
    return Choice(channels[best.channel], reason)
