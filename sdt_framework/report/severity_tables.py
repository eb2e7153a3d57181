"""The "Severity and alarms" section's per-condition zone and alarm tables (:mod:`.severity`).

Both read :class:`~sdt_framework.severity.Agreement`: the zone each sensor
grades per machine and condition (the worst channel's median V_RMS, the share
of that channel's windows behind it), and the criterion II alarms on each
sensor's own baseline with the reference's baseline beside.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..severity import Agreement
from .document import Table, literal

__all__ = ["alarm_table", "condition_cells", "condition_table"]


def _pct(value: float) -> str:
    return "–" if value is None or np.isnan(value) else f"{100 * value:.1f} %"


def _ci(low: float, high: float) -> str:
    return "–" if np.isnan(low) else f"[{100 * low:.1f}, {100 * high:.1f}]"


def _mm(value: float) -> str:
    return "–" if np.isnan(value) else f"{value:.2f}"


def condition_cells(agreement: Agreement) -> tuple[list[str], list[tuple[str, ...]]]:
    """(sensors, rows): per machine and condition (with level), each sensor's cell.

    A cell reads "C 3.21 ch4 (88 %)": zone, median V_RMS in mm/s at the channel
    that grades the machine (the worst), the share of that channel's windows in
    the zone; "≠" marks a sensor whose zone differs from the reference's.
    """
    table = agreement.conditions
    machine_rows = table[table["channel"] == "all"]
    sensors = list(dict.fromkeys(machine_rows["sensor"]))
    rows = []
    keys = ["machine", "condition", "severity"]
    for (machine, condition, level), part in machine_rows.groupby(keys, dropna=False, sort=False):
        cells = part.set_index("sensor")
        ref_zone = cells.loc[agreement.reference, "zone"]
        out = []
        for sensor in sensors:
            if sensor not in cells.index:
                out.append("–")
                continue
            r = cells.loc[sensor]
            mark = " ≠" if r["zone"] != ref_zone else ""
            out.append(
                f"{r['zone']} {r['v_rms']:.2f} {r['from_channel']} ({100 * r['share']:.0f} %){mark}"
            )
        name = condition if pd.isna(level) else f"{condition} {int(level)}"
        rows.append((str(machine), str(name), *out))
    return sensors, rows


def condition_table(agreement: Agreement) -> Table:
    """The per-condition zone table of the report."""
    sensors, rows = condition_cells(agreement)
    header = ("machine", "condition", *(literal(s) for s in sensors))
    note = (
        "zone of the median V_RMS (mm/s) of the condition's windows at the channel that "
        "grades the machine (the largest, as ISO grades by the highest bearing), and the "
        "share of that channel's windows in that zone; ≠: not the reference's zone"
    )
    return Table(header, tuple(tuple(literal(c) for c in row) for row in rows), note)


def alarm_table(agreement: Agreement) -> Table:
    """Criterion II alarms per machine, channel and sensor: own baseline, reference's beside."""
    rows = tuple(
        (
            literal(r.machine),
            literal(r.channel),
            literal(r.sensor),
            f"{_mm(r.baseline)} ({_mm(r.baseline_ref)})",
            f"{_mm(r.alarm)}{' *' if r.capped else ''} ({_mm(r.alarm_ref)})",
            f"{r.trip:.2f}",
            f"{_pct(r.fault_alarm_same)} {_ci(r.ci_low, r.ci_high)}",
            _pct(r.fault_alarm_same_refbase),
            f"{_pct(r.fault_alarm_sensor)} ({_pct(r.fault_alarm_ref)})",
            _pct(r.missed),
            f"{_pct(r.false_alarm_sensor)} ({_pct(r.false_alarm_ref)})",
            _pct(r.trip_same),
        )
        for r in agreement.alarms.itertuples()
    )
    header = (
        "machine",
        "channel",
        "sensor",
        "baseline, own (reference's), mm/s",
        "ALARM, own (reference's)",
        "TRIP",
        "fault windows alarmed as the reference, own baseline [95 % CI]",
        "the same on the reference's baseline",
        "fault windows alarmed (reference)",
        "missed alarms",
        "false alarms, healthy (reference)",
        "TRIP as reference",
    )
    notes = []
    if agreement.alarms["capped"].any():
        notes.append(
            "* capped at 1.25 x B/C: the healthy baseline is already above B/C (zone C or D by "
            "this table), so the ALARM sits below it and healthy windows alarm"
        )
    return Table(header, rows, "; ".join(notes))
