"""``sdt compare``'s severity part: ISO zone and alarm agreement of each sensor (text and JSON)."""

from __future__ import annotations

import json
from typing import Any

from rich.table import Table

from ..errors import SDTError
from .common import console, print_table

__all__ = ["check_zones", "print_severity", "severity_agreement", "severity_json"]


def severity_agreement(
    folder: Any, zones: list[str] | None, reference: str, seed: int = 0
) -> tuple[Any, str]:
    """Zone agreement of ``folder``'s sensors with ``reference`` (the comparison's baseline).

    The tables: ``--zones``, else the folder's ``[benchmark] zones``, else the defaults.

    None and the reason when it cannot be computed (no features, no table, no
    windows of ``reference``); a bad ``--zones`` value is an error.
    """
    from ..severity import assign_tables, zone_agreement

    features = folder.features
    if features is None or features.empty or "V_RMS" not in features.columns:
        return None, "features.parquet with V_RMS is missing: no zone agreement"
    config = folder.config
    assignments = assign_tables(
        sorted(features["machine"].unique()),
        zones or [],
        configured=config.zones if config is not None else None,
        where=f"{folder.path / 'config.toml'}: [benchmark] zones",
    )
    if not assignments:
        return None, "no zone table for these machines; give --zones TABLE or MACHINE=TABLE"
    if not (features["sensor"] == reference).any():
        return None, f"features.parquet has no windows of {reference!r} to grade against"
    return zone_agreement(features, reference, assignments, seed=seed), ""


def _pct(value: float) -> str:
    return "–" if value != value else f"{100 * value:.1f} %"


def print_severity(agreement: Any) -> None:
    """One row per machine and sensor, pooled over channels: zone and alarm agreement."""
    zones, alarms = agreement.zones, agreement.alarms
    pooled = zones["channel"] == "all"
    keys = ["machine", "channel", "sensor"]
    merged = zones[pooled if pooled.any() else ~pooled].merge(alarms, on=keys, suffixes=("", "_a"))
    out = Table(
        title=f"ISO zones of V_RMS (10-1000 Hz) against {agreement.reference}, all channels",
        title_justify="left",
    )
    for column in ("machine", "sensor", "same zone [95 % CI]", "better zone", "alarm as ref"):
        out.add_column(column)
    out.add_column("false alarms (ref)")
    for r in merged.itertuples():
        ci = "" if r.ci_low != r.ci_low else f" [{100 * r.ci_low:.1f}, {100 * r.ci_high:.1f}]"
        out.add_row(
            r.machine,
            r.sensor,
            f"{_pct(r.share_same)}{ci}",
            _pct(r.share_better),
            _pct(r.fault_alarm_same),
            f"{_pct(r.false_alarm_sensor)} ({_pct(r.false_alarm_ref)})",
        )
    print_table(out)
    for a in agreement.assignments.values():
        text = f"{a.machine} zone table: {a.table.name} ({a.table.source})"
        console.print(text, highlight=False, soft_wrap=True)


def severity_json(agreement: Any, note: str) -> dict[str, Any]:
    """The severity figures for ``--json``: tables used, zones, confusion, alarms."""
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
                "boundaries_mm_s": a.table.boundaries.model_dump(),
                "why": a.reason,
            }
            for a in agreement.assignments.values()
        },
        "unassigned": agreement.unassigned,
        "zones": records(agreement.zones),
        "confusion": records(agreement.confusion),
        "alarms": records(agreement.alarms),
    }


def check_zones(zones: list[str] | None) -> None:
    """Read and validate every --zones table before any other work (a bad one: one line)."""
    from ..severity import resolve_table

    for value in zones or []:
        table = value.rpartition("=")[2]
        if not table.strip():
            raise SDTError(f"--zones {value!r}: give TABLE or MACHINE=TABLE")
        resolve_table(table)
