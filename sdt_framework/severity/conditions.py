"""The zone each sensor grades per machine and condition: "cavitation 3: reference C, ADXL345 D".

Per machine, condition (and level), channel and sensor: the median V_RMS of
the condition's windows at that channel, the zone it grades in, and the share
of those windows graded in that same zone (how firmly the windows stand behind
it). The median, not the mean: a few transient windows do not move the grade.
Per machine and condition ("all" channels), the zone is the worst channel's:
ISO grades a machine by its vibration severity, the largest broad-band value
measured at any bearing (ISO 20816-1:2016 6.3.2, as transcribed in
docs/severity.md); the channel it comes from is named. The reference and each
sensor are graded on the same windows (those paired with the reference's).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from .tables import ZONES, Assignment

__all__ = ["condition_zones"]

_KEYS = ["machine", "condition", "severity"]
_WINDOW = ["machine", "channel", "recording_id", "acquisition", "window"]


def condition_zones(
    pairs: pd.DataFrame, reference: str, assignments: dict[str, Assignment]
) -> pd.DataFrame:
    """The zone per machine, condition, level, channel and sensor (reference first).

    ``pairs`` is :func:`.agreement.paired_zones`'s table. Columns: machine,
    condition, severity (level; NA for healthy), channel ("all" for the
    machine's grade), sensor, v_rms (median, mm/s), zone (A-D), share (of the
    channel's windows in that zone), n_windows, from_channel (the channel an
    "all" row's grade comes from; the row's own channel otherwise).
    """
    ref = pairs.drop_duplicates(_WINDOW)[[*_KEYS, "channel", "v_ref"]].assign(sensor=reference)
    long = pd.concat(
        [
            ref.rename(columns={"v_ref": "v"}),
            pairs[[*_KEYS, "channel", "sensor", "v_sensor"]].rename(columns={"v_sensor": "v"}),
        ],
        ignore_index=True,
    )
    order = list(assignments)
    cuts = np.stack([assignments[m].table.cuts for m in order])
    long["cut_row"] = long["machine"].map({m: i for i, m in enumerate(order)}).astype(int)
    groups = [*_KEYS, "channel", "sensor"]
    table = long.groupby(groups, dropna=False, sort=False).agg(
        v_rms=("v", "median"), n_windows=("v", "size"), cut_row=("cut_row", "first")
    )
    table = table.reset_index()
    zone = (table["v_rms"].to_numpy(float)[:, None] > cuts[table["cut_row"]]).sum(axis=1)
    table["zone_index"] = zone
    # share of the group's windows graded in the zone of its median
    long = long.merge(table[[*groups, "zone_index"]], on=groups, how="left")
    window_zone = (long["v"].to_numpy(float)[:, None] > cuts[long["cut_row"]]).sum(axis=1)
    long["in_zone"] = window_zone == long["zone_index"].to_numpy()
    share = long.groupby(groups, dropna=False, sort=False)["in_zone"].mean().rename("share")
    table = table.merge(share.reset_index(), on=groups, how="left")
    table["from_channel"] = table["channel"].astype(str)
    worst = table.sort_values("v_rms", ascending=False, kind="stable")
    machine_rows = worst.drop_duplicates([*_KEYS, "sensor"]).assign(channel="all")
    out = pd.concat([table.assign(channel=table["channel"].astype(str)), machine_rows])
    out["zone"] = np.asarray(ZONES)[out["zone_index"].to_numpy(int)]
    sensors = [reference, *sorted(set(pairs["sensor"]))]
    out["sensor"] = pd.Categorical(out["sensor"], categories=sensors, ordered=True)
    out = out.sort_values([*_KEYS, "channel", "sensor"], kind="stable", na_position="first")
    out["sensor"] = out["sensor"].astype(str)
    columns = [*_KEYS, "channel", "sensor", "v_rms", "zone", "share", "n_windows", "from_channel"]
    return out[columns].reset_index(drop=True)
