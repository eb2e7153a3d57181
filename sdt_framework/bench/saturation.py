"""How much of each recording a sensor saw at its full scale: saturation, said aloud.

A twin clips at ``+-full_scale_g`` (chain stage 6), as the real part would. A
few clipped peaks are what the comparison is for; a recording mostly at full
scale (87 % of the samples of a cavitation run at +-16 g) is a different
measurement, a square wave, and a Macro F1 computed on it must say so. The
count is taken on each block's degraded signal (samples with
``|x| >= full_scale_g``), cached with the block, so a resumed or cached run
reports the same figures. Repetition 0 of the nominal profile (or unit 0) is
counted: the noise of later repetitions moves a handful of samples, not the
picture.
"""

from __future__ import annotations

from collections.abc import Iterable

import pandas as pd

from .featurise import FeatureBlock

__all__ = ["WARN_FRACTION", "saturation_lines", "saturation_summary", "saturation_table"]

#: a recording with at least this share of samples at full scale is named in a warning
WARN_FRACTION = 0.01

_COLUMNS = ["sensor", "recording_id", "full_scale_g", "at_full_scale", "samples", "fraction"]


def saturation_table(
    blocks: Iterable[FeatureBlock], full_scale: dict[str, float | None]
) -> pd.DataFrame:
    """One row per (sensor, recording) with a full scale: samples at it, and their share."""
    rows = [
        (b.sensor, b.recording_id, full_scale.get(b.sensor), b.at_full_scale, b.samples)
        for b in blocks
        if b.repeat == 0 and b.unit in (-1, 0) and b.samples and full_scale.get(b.sensor)
    ]
    table = pd.DataFrame(rows, columns=_COLUMNS[:-1]).drop_duplicates(["sensor", "recording_id"])
    table["fraction"] = table["at_full_scale"] / table["samples"].where(table["samples"] > 0)
    return table.sort_values(["sensor", "recording_id"], ignore_index=True)[_COLUMNS]


def saturation_summary(table: pd.DataFrame) -> dict[str, dict]:
    """Per sensor: overall share of samples at full scale and the recordings above the limit."""
    summary: dict[str, dict] = {}
    for sensor, rows in table.groupby("sensor", sort=True):
        above = rows[rows["fraction"] >= WARN_FRACTION].sort_values("fraction", ascending=False)
        summary[str(sensor)] = {
            "full_scale_g": float(rows["full_scale_g"].iloc[0]),
            "fraction": float(rows["at_full_scale"].sum() / rows["samples"].sum()),
            "recordings": len(rows),
            "recordings_above_limit": len(above),
            "limit": WARN_FRACTION,
            "worst": [
                {"recording_id": r.recording_id, "fraction": round(float(r.fraction), 6)}
                for r in above.head(5).itertuples()
            ],
        }
    return summary


def saturation_lines(summary: dict[str, dict]) -> list[str]:
    """One sentence per sensor that saturates in some recording (for the terminal)."""
    lines = []
    for sensor, entry in summary.items():
        if not entry["recordings_above_limit"]:
            continue
        worst = ", ".join(f"{w['recording_id']} {w['fraction']:.0%}" for w in entry["worst"][:3])
        more = entry["recordings_above_limit"] - min(3, len(entry["worst"]))
        lines.append(
            f"{sensor} is at its +-{entry['full_scale_g']:g} g full scale (clipped) in "
            f"{entry['recordings_above_limit']} of {entry['recordings']} recordings for at least "
            f"{entry['limit']:.0%} of the samples: {worst}"
            + (f" and {more} more" if more > 0 else "")
            + " (summary.json, saturation)"
        )
    return lines
