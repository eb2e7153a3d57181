"""Zone and alarm agreement of every sensor with the reference, from features.parquet.

Each window's V_RMS (10-1000 Hz, mm/s) is graded A-D by its machine's zone
table (:mod:`.tables`), for the reference and for each sensor; windows are
paired by machine, channel, recording, acquisition and window index. Per
machine and channel (and per machine over all channels, "all"): the share of
windows graded in the same zone, the zone confusion matrix (reference rows,
sensor columns) and the share graded in a *better* zone than the reference
(the dangerous error: the node would report a healthier machine than it is).

Alarms follow criterion II on each sensor's own healthy baseline, decreases
counted, with the same windows judged on the reference's baseline beside
(:mod:`.alarms`; ISO 10816-3:2009 5.3, 5.4.1, 5.4.2). Per machine, condition
and level, the zone each sensor grades (:mod:`.conditions`). The band each
sensor's V_RMS covers (the table's, clipped to its chain) is checked when the
chains' bandwidths are given (:mod:`.bands`).

Intervals are at the recording level, as ``sdt compare`` gives them for Macro
F1 (:mod:`sdt_framework.verdict.recordings`): recordings are drawn with
replacement within each condition, and the share recomputed per draw.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..errors import SDTError
from ..seeding import rng
from ..verdict.recordings import stratified_weights
from .alarms import RULE, CriterionII, alarm_bits, alarm_thresholds
from .bands import vrms_bands
from .conditions import condition_zones
from .tables import ZONES, Assignment, band_problem

__all__ = ["Agreement", "paired_zones", "window_agreement", "zone_agreement"]

_WINDOW = ["machine", "channel", "recording_id", "acquisition", "window"]


@dataclass
class Agreement:
    """Zone and alarm agreement tables (one row per machine, channel and sensor)."""

    reference: str
    zones: pd.DataFrame  # share_same (+ interval), share_better, share_worse, n_windows
    confusion: pd.DataFrame  # long: machine, channel, sensor, reference_zone, sensor_zone, count
    alarms: pd.DataFrame  # thresholds and agreement per machine, channel, sensor
    assignments: dict[str, Assignment]
    unassigned: list[str]  # machines without a zone table (left out)
    conditions: pd.DataFrame  # zone per machine, condition, level, channel, sensor
    bands: pd.DataFrame  # the V_RMS band each sensor covers (empty: not checked)
    warnings: list[str]  # one line per sensor whose band is clipped or not checked
    rule: CriterionII = RULE


def paired_zones(
    features: pd.DataFrame, reference: str, assignments: dict[str, Assignment]
) -> pd.DataFrame:
    """One row per (sensor window, reference window) pair with both V_RMS and zones."""
    need = {*_WINDOW, "sensor", "condition", "severity", "V_RMS"}
    missing = sorted(need - set(features.columns))
    if missing:
        raise SDTError(f"features.parquet lacks column(s) {missing}: the severity needs V_RMS")
    if not assignments:
        machines = ", ".join(map(str, sorted(features["machine"].unique())))
        raise SDTError(
            f"no zone table grades machine(s) {machines}; name one per machine with "
            f"zones = {{ MACHINE = 'TABLE' }} under [benchmark] or sdt compare --zones"
        )
    for assignment in assignments.values():
        problem = band_problem(assignment.table)
        if problem:
            raise SDTError(f"{assignment.machine}: {problem}")
    frame = features[features["machine"].isin(list(assignments))]
    if "unit" in frame.columns:  # per-unit runs: the first unit of each sensor
        frame = frame[frame["unit"] == frame.groupby("sensor")["unit"].transform("min")]
    ref = frame[frame["sensor"] == reference]
    if ref.empty:
        raise SDTError(f"features.parquet has no windows of the reference {reference!r}")
    ref = ref[[*_WINDOW, "condition", "severity", "V_RMS"]].rename(columns={"V_RMS": "v_ref"})
    others = frame[frame["sensor"] != reference][[*_WINDOW, "sensor", "V_RMS"]]
    pairs = others.merge(ref, on=_WINDOW, how="inner").rename(columns={"V_RMS": "v_sensor"})
    order = list(assignments)
    table_cuts = np.stack([assignments[m].table.cuts for m in order])
    cuts = table_cuts[pairs["machine"].map({m: i for i, m in enumerate(order)}).to_numpy(int)]
    for side in ("ref", "sensor"):  # zone = number of boundaries below the value
        values = pairs[f"v_{side}"].to_numpy(float)
        pairs[f"zone_{side}"] = (values[:, None] > cuts).sum(axis=1)
    pairs["healthy"] = pairs["severity"].isna().to_numpy()
    return pairs


def window_agreement(
    features: pd.DataFrame, reference: str, assignments: dict[str, Assignment]
) -> pd.DataFrame:
    """Per machine and sensor, all channels: the share of windows in the reference's zone.

    The point estimate of :func:`zone_agreement`'s pooled row, without its
    intervals or alarms (``sdt explore`` asks it of every design point).
    """
    pairs = paired_zones(features, reference, assignments)
    pairs["same"] = pairs["zone_ref"] == pairs["zone_sensor"]
    pairs["better"] = pairs["zone_sensor"] < pairs["zone_ref"]
    grouped = pairs.groupby(["machine", "sensor"], sort=True)
    return grouped.agg(
        zone_agreement=("same", "mean"), share_better=("better", "mean"), n_windows=("same", "size")
    ).reset_index()


def _interval(
    frame: pd.DataFrame, hit: str, key: tuple, n_boot: int, seed: int
) -> tuple[float, float]:
    """95 % percentile interval of the share ``hit`` over recordings resampled per condition."""
    per = frame.groupby("recording_id").agg(
        n=(hit, "size"), k=(hit, "sum"), c=("condition", "first")
    )
    if per["c"].value_counts().min() < 2:
        return np.nan, np.nan
    weights = stratified_weights(per["c"].to_numpy(), n_boot, rng(seed, "severity", *key))
    shares = (weights @ per["k"].to_numpy(float)) / (weights @ per["n"].to_numpy(float))
    low, high = np.percentile(shares, [2.5, 97.5])
    return float(low), float(high)


def _scopes(pairs: pd.DataFrame):
    """(machine, channel, sensor, rows) per channel and per machine over all channels."""
    for (machine, channel, sensor), rows in pairs.groupby(["machine", "channel", "sensor"]):
        yield machine, str(channel), sensor, rows
    for (machine, sensor), rows in pairs.groupby(["machine", "sensor"]):
        if rows["channel"].nunique() > 1:
            yield machine, "all", sensor, rows


def _alarm_row(rows: pd.DataFrame, channel: str, key: tuple, n_boot: int, seed: int) -> dict:
    """Alarm agreement of one scope: own baseline, then the reference's baseline beside it."""
    fault, healthy = rows[~rows["healthy"]], rows[rows["healthy"]]
    low, high = _interval(fault, "alarm_same", (*key, "alarm"), n_boot, seed)
    one = channel != "all"  # thresholds differ per channel: none for the pooled row
    first = rows.iloc[0]
    return {
        "baseline": first["baseline"] if one else np.nan,
        "alarm": first["alarm"] if one else np.nan,
        "capped": bool(first["capped"]) if one else False,
        "baseline_ref": first["baseline_ref"] if one else np.nan,
        "alarm_ref": first["alarm_ref"] if one else np.nan,
        "capped_ref": bool(first["capped_ref"]) if one else False,
        "trip": first["trip"],
        "n_fault": len(fault),
        "n_healthy": len(healthy),
        "fault_alarm_ref": fault["bit_ref"].mean(),
        "fault_alarm_sensor": fault["bit_sensor"].mean(),
        "fault_alarm_same": fault["alarm_same"].mean(),
        "ci_low": low,
        "ci_high": high,
        "missed": (fault["bit_ref"] & ~fault["bit_sensor"]).mean(),
        "false_alarm_ref": healthy["bit_ref"].mean(),
        "false_alarm_sensor": healthy["bit_sensor"].mean(),
        "fault_alarm_same_refbase": fault["alarm_same_refbase"].mean(),
        "missed_refbase": (fault["bit_ref"] & ~fault["bit_refbase"]).mean(),
        "false_alarm_sensor_refbase": healthy["bit_refbase"].mean(),
        "trip_same": rows["trip_same"].mean(),
    }


def zone_agreement(
    features: pd.DataFrame,
    reference: str,
    assignments: dict[str, Assignment],
    *,
    n_boot: int = 2000,
    seed: int = 0,
    bandwidths: Mapping[str, float | None] | None = None,
) -> Agreement:
    """Zone and alarm agreement of each sensor with ``reference`` (see the module doc).

    ``bandwidths`` (sensor -> its chain's bandwidth in Hz, :func:`.chain_bandwidth`)
    checks the band each sensor's V_RMS covers; without it the band is not
    checked and :attr:`Agreement.warnings` says so.

    Raises
    ------
    SDTError
        When no window of another sensor pairs with a reference window (a
        reference-only benchmark, or every other profile skipped): nothing to grade.
    """
    machines = sorted(features["machine"].unique())
    unassigned = [m for m in machines if m not in assignments]
    pairs = paired_zones(features, reference, assignments)
    if pairs.empty:
        graded = features["machine"].isin(list(assignments))
        others = features.loc[graded & (features["sensor"] != reference), "sensor"].unique()
        raise SDTError(
            f"no sensor besides the reference {reference!r} has windows to grade against it"
            if len(others) == 0
            else f"no window of {', '.join(map(repr, others))} pairs with one of the reference "
            f"{reference!r} (same machine, channel, recording, acquisition and window)"
        )
    thresholds = alarm_thresholds(pairs, assignments)
    pairs = alarm_bits(pairs.merge(thresholds, on=["machine", "channel", "sensor"], how="left"))
    pairs["same"] = pairs["zone_ref"] == pairs["zone_sensor"]
    pairs["better"] = pairs["zone_sensor"] < pairs["zone_ref"]
    zones, alarms, confusion = [], [], []
    for machine, channel, sensor, rows in _scopes(pairs):
        key = (machine, channel, sensor)
        low, high = _interval(rows, "same", key, n_boot, seed)
        head = {"machine": machine, "channel": channel, "sensor": sensor}
        zones.append(
            {
                **head,
                "table": assignments[machine].table.name,
                "n_windows": len(rows),
                "n_recordings": rows["recording_id"].nunique(),
                "share_same": rows["same"].mean(),
                "ci_low": low,
                "ci_high": high,
                "share_better": rows["better"].mean(),
                "share_worse": (rows["zone_sensor"] > rows["zone_ref"]).mean(),
            }
        )
        counts = np.zeros((4, 4), dtype=np.int64)
        np.add.at(counts, (rows["zone_ref"].to_numpy(), rows["zone_sensor"].to_numpy()), 1)
        confusion += [
            (machine, channel, sensor, ZONES[i], ZONES[j], int(counts[i, j]))
            for i in range(4)
            for j in range(4)
        ]
        alarms.append({**head, **_alarm_row(rows, channel, key, n_boot, seed)})
    sensors = [reference, *sorted(pairs["sensor"].unique())]
    bands, warnings = vrms_bands({s: (bandwidths or {}).get(s) for s in sensors})
    if bandwidths is None:
        bands, warnings = bands.iloc[:0], ["chain bandwidths not given: V_RMS bands not checked"]
    columns = ["machine", "channel", "sensor", "reference_zone", "sensor_zone", "count"]
    return Agreement(
        reference,
        pd.DataFrame(zones),
        pd.DataFrame(confusion, columns=columns),
        pd.DataFrame(alarms),
        assignments,
        unassigned,
        condition_zones(pairs, reference, assignments),
        bands,
        warnings,
    )


#: why a results folder's windows cannot be graded when its feature set holds no V_RMS
#: (the ISO zones grade each window's velocity RMS, a paper8 feature; ``orders`` has none)
NO_VRMS = (
    "features.parquet holds no V_RMS (this run's feature set does not compute it): the ISO "
    "zones grade each window's V_RMS, a paper8 feature; run with a set that holds it (e.g. "
    "--features paper8+orders) to grade the windows"
)
