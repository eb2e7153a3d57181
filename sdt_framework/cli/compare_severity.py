"""``sdt compare``'s severity part: ISO zone and alarm agreement of each sensor (text and JSON)."""

from __future__ import annotations

import json
from typing import Any

from rich.table import Table

from ..errors import SDTError
from .common import console, print_table, warn

__all__ = ["check_zones", "print_severity", "severity_agreement", "severity_json"]


def severity_agreement(
    folder: Any, zones: list[str] | None, reference: str, seed: int = 0, registry: Any = None
) -> tuple[Any, str]:
    """Zone agreement of ``folder``'s sensors with ``reference`` (the comparison's baseline).

    The tables: ``--zones``, else the folder's ``[benchmark] zones``, else the
    one each machine's spec names (the folder's dataset's machines and its
    config's ``machine_specs``, :func:`~sdt_framework.report.machines.folder_machines`).
    With ``registry``, each sensor's V_RMS band is checked against its chain.

    None and the reason when it cannot be computed (no features, no table, no
    windows of ``reference``); a bad ``--zones`` value is an error.
    """
    from ..report import folder_machines, no_spec_line
    from ..severity import NO_VRMS, assign_tables, sensor_bandwidths, zone_agreement

    features = folder.features
    if features is None or features.empty:
        return None, "features.parquet with V_RMS is missing: no zone agreement"
    if "V_RMS" not in features.columns:
        return None, f"{NO_VRMS}: no zone agreement"
    config = folder.config
    machines = sorted(features["machine"].unique())
    specs = folder_machines(folder, registry).specs
    assignments = assign_tables(
        machines,
        zones or [],
        configured=config.zones if config is not None else None,
        where=f"{folder.path / 'config.toml'}: [benchmark] zones",
        window_s=config.window_s if config is not None else None,
        specs=specs,
    )
    if not assignments:
        lacking = "; ".join(no_spec_line(m) for m in machines if m not in specs)
        return None, "no zone table for these machines; give --zones TABLE or MACHINE=TABLE" + (
            f" ({lacking})" if lacking else ""
        )
    if not (features["sensor"] == reference).any():
        return None, f"features.parquet has no windows of {reference!r} to grade against"
    bandwidths = None
    if registry is not None:
        bandwidths = sensor_bandwidths(features["sensor"].unique(), registry.sensor)
    return zone_agreement(features, reference, assignments, seed=seed, bandwidths=bandwidths), ""


def _pct(value: float) -> str:
    return "–" if value != value else f"{100 * value:.1f} %"


def _band(agreement: Any, sensor: str) -> str:
    bands = agreement.bands
    row = bands[bands["sensor"] == sensor]
    return "10-1000 Hz (not checked)" if row.empty else str(row["label"].iloc[0])


def print_severity(agreement: Any) -> None:
    """Per machine and sensor, pooled over channels: zone and alarm agreement; then the zone
    per condition, the tables used and a warning per sensor whose V_RMS band is clipped."""
    from ..report import condition_cells

    zones, alarms = agreement.zones, agreement.alarms
    pooled = zones["channel"] == "all"
    keys = ["machine", "channel", "sensor"]
    merged = zones[pooled if pooled.any() else ~pooled].merge(alarms, on=keys, suffixes=("", "_a"))
    out = Table(
        title=f"ISO zones of V_RMS (10-1000 Hz) against {agreement.reference}, all channels",
        title_justify="left",
    )
    for column in ("machine", "sensor", "V_RMS band", "same zone [95 % CI]", "better zone"):
        out.add_column(column)
    for column in ("alarm as ref, own baseline", "on ref's baseline", "false alarms (ref)"):
        out.add_column(column)
    for r in merged.itertuples():
        ci = "" if r.ci_low != r.ci_low else f" [{100 * r.ci_low:.1f}, {100 * r.ci_high:.1f}]"
        out.add_row(
            r.machine,
            r.sensor,
            _band(agreement, r.sensor),
            f"{_pct(r.share_same)}{ci}",
            _pct(r.share_better),
            _pct(r.fault_alarm_same),
            _pct(r.fault_alarm_same_refbase),
            f"{_pct(r.false_alarm_sensor)} ({_pct(r.false_alarm_ref)})",
        )
    print_table(out)
    sensors, rows = condition_cells(agreement)
    per = Table(
        title="ISO zone per condition: median V_RMS (mm/s) at the worst channel, share of its "
        "windows in that zone (≠: not the reference's zone)",
        title_justify="left",
    )
    for column in ("machine", "condition", *sensors):
        per.add_column(column)
    for row in rows:
        per.add_row(*row)
    print_table(per)
    rule = agreement.rule
    console.print(
        f"alarms: criterion II ({rule.source}) on each sensor's own healthy baseline, "
        "decreases counted; 'on ref's baseline' judges the sensor by the reference's",
        highlight=False,
        soft_wrap=True,
    )
    for a in agreement.assignments.values():
        text = f"{a.machine} zone table: {a.table.name} ({a.table.source}); {a.reason}"
        console.print(text, highlight=False, soft_wrap=True)
    for line in agreement.warnings:
        warn(line)


def severity_json(agreement: Any, note: str) -> dict[str, Any]:
    """The severity figures for ``--json``: tables used, zones, conditions, confusion, alarms."""
    if agreement is None:
        return {"note": note}

    def records(frame):
        return json.loads(frame.to_json(orient="records"))

    return {
        "reference": agreement.reference,
        "tables": {
            a.machine: {
                "name": a.table.name,
                "source": a.table.source,
                "band_hz": list(a.table.band_hz),
                "boundaries_mm_s": a.table.boundaries.model_dump(),
                "why": a.reason,
            }
            for a in agreement.assignments.values()
        },
        "unassigned": agreement.unassigned,
        "bands": records(agreement.bands),
        "warnings": agreement.warnings,
        "alarm_rule": agreement.rule.source,
        "zones": records(agreement.zones),
        "conditions": records(agreement.conditions),
        "confusion": records(agreement.confusion),
        "alarms": records(agreement.alarms),
    }


def check_zones(zones: list[str] | None) -> None:
    """Read and validate every --zones table before any other work (a bad one: one line)."""
    from ..severity import band_problem, resolve_table

    for value in zones or []:
        table = value.rpartition("=")[2]
        if not table.strip():
            raise SDTError(f"--zones {value!r}: give TABLE or MACHINE=TABLE")
        problem = band_problem(resolve_table(table))
        if problem:
            raise SDTError(f"--zones {value!r}: {problem}")
