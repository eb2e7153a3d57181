"""The report's "Severity and alarms" section: ISO zones and alarms, and the field's spectra.

Tables from :mod:`sdt_framework.severity` on the folder's features.parquet
(zone tables used and why, zone agreement with recording-level intervals,
zone confusion per machine, criterion II alarms), then the spectral figures
(:mod:`.figures_severity`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SDTError
from ..severity import ZONES, Agreement, assign_tables, zone_agreement
from .document import Block, Heading, Paragraph, Table, literal
from .figures_severity import spectral_blocks
from .load import ResultsFolder

__all__ = ["agreement_rows", "folder_agreement", "severity_blocks"]


def _pct(value: float) -> str:
    return "–" if value is None or np.isnan(value) else f"{100 * value:.1f} %"


def _ci(low: float, high: float) -> str:
    return "–" if np.isnan(low) else f"[{100 * low:.1f}, {100 * high:.1f}]"


def agreement_rows(agreement: Agreement, channels: str = "every") -> list[tuple[str, ...]]:
    """Zone agreement rows (machine, channel, sensor, table, same, CI, better, worse, n)."""
    zones = agreement.zones
    if channels == "all":
        pooled = zones[zones["channel"] == "all"]
        zones = pooled if not pooled.empty else zones
    return [
        (
            literal(r.machine),
            literal(r.channel),
            literal(r.sensor),
            literal(r.table),
            _pct(r.share_same),
            _ci(r.ci_low, r.ci_high),
            _pct(r.share_better),
            _pct(r.share_worse),
            f"{r.n_windows} / {r.n_recordings}",
        )
        for r in zones.itertuples()
    ]


AGREEMENT_HEADER = (
    "machine",
    "channel",
    "sensor",
    "zone table",
    "same zone",
    "95 % CI (recordings)",
    "better zone (dangerous)",
    "worse zone",
    "windows / recordings",
)


def _tables_used(agreement: Agreement) -> list[Block]:
    rows = tuple(
        (
            literal(a.machine),
            literal(a.table.name),
            f"{a.table.boundaries.a_b:g} / {a.table.boundaries.b_c:g} / {a.table.boundaries.c_d:g}",
            literal(a.table.source),
            literal(a.reason),
        )
        for a in agreement.assignments.values()
    )
    blocks: list[Block] = [
        Table(("machine", "zone table", "A/B / B/C / C/D (mm/s)", "source", "why"), rows)
    ]
    if agreement.unassigned:
        blocks.append(
            Paragraph(
                f"No zone table for {', '.join(map(literal, agreement.unassigned))}: left out "
                f"(`zones = {{ MACHINE = 'TABLE' }}` under `[benchmark]` in the config, or "
                f"`sdt compare --zones MACHINE=TABLE`, grades it)."
            )
        )
    return blocks


def _confusions(agreement: Agreement) -> list[Block]:
    conf = agreement.confusion
    pooled = conf[conf["channel"] == "all"]
    conf = pooled if not pooled.empty else conf
    blocks: list[Block] = []
    for (machine, channel, sensor), part in conf.groupby(["machine", "channel", "sensor"]):
        counts = part.pivot(index="reference_zone", columns="sensor_zone", values="count")
        counts = counts.reindex(index=list(ZONES), columns=list(ZONES), fill_value=0)
        rows = tuple((z, *(str(int(v)) for v in counts.loc[z])) for z in ZONES)
        title = f"{literal(machine)} {literal(channel)}: reference \\ {literal(sensor)}"
        blocks.append(
            Table(
                (title, *ZONES),
                rows,
                "windows; above the diagonal the sensor grades worse, below it better",
            )
        )
    return blocks


def _alarms(agreement: Agreement) -> Table:
    rows = tuple(
        (
            literal(r.machine),
            literal(r.channel),
            literal(r.sensor),
            "–" if np.isnan(r.baseline) else f"{r.baseline:.2f}",
            "–" if np.isnan(r.alarm) else f"{r.alarm:.2f}{' *' if r.capped else ''}",
            f"{r.trip:.2f}",
            f"{_pct(r.fault_alarm_same)} {_ci(r.ci_low, r.ci_high)}",
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
        "baseline (mm/s)",
        "ALARM",
        "TRIP",
        "fault windows alarmed as the reference [95 % CI]",
        "fault windows alarmed (reference)",
        "missed alarms",
        "false alarms, healthy (reference)",
        "TRIP as reference",
    )
    note = (
        "* capped at 1.25 x B/C: the reference's healthy baseline is already above B/C "
        "(zone C or D by this table), so the ALARM sits below it and healthy windows alarm"
        if agreement.alarms["capped"].any()
        else ""
    )
    return Table(header, rows, note)


def folder_agreement(folder: ResultsFolder) -> Agreement:
    """The folder's zone and alarm agreement with the reference, computed once.

    The "Severity and alarms" section and the decision table both show it;
    its recording bootstrap is the costly part, so the result (or the
    :class:`SDTError` saying why there is none) is kept on the folder.
    """
    if folder.agreement is None:
        try:
            folder.agreement = _agreement(folder)
        except SDTError as exc:
            folder.agreement = exc
    if isinstance(folder.agreement, SDTError):
        raise folder.agreement
    return folder.agreement


def _agreement(folder: ResultsFolder) -> Agreement:
    features = folder.features
    if features is None or features.empty or "V_RMS" not in features.columns:
        raise SDTError("features.parquet with V_RMS is missing.")
    config = folder.config
    assignments = assign_tables(
        sorted(features["machine"].unique()),
        configured=config.zones if config is not None else None,
        where=f"{folder.path / 'config.toml'}: [benchmark] zones",
    )
    seed = config.seed if config is not None else 0
    return zone_agreement(features, folder.reference, assignments, seed=seed)


def severity_blocks(
    folder: ResultsFolder, registry: Any, figures_dir: Path, colors: dict[str, str]
) -> list[Block]:
    """The whole section; a note instead of the tables when features.parquet is absent."""
    blocks: list[Block] = [Heading("Severity and alarms", 2)]
    try:
        agreement = folder_agreement(folder)
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not shown: {literal(exc)}")]
    blocks += [
        Paragraph(
            "How a condition-monitoring engineer grades the machine: each window's V_RMS "
            "(velocity r.m.s., 10-1000 Hz, mm/s) in ISO zones A (new machine), B "
            "(unrestricted long-term operation), C (limited period), D (damage), by each "
            "sensor and by the reference, windows paired one to one (repetition 0). "
            "'Better zone' is the dangerous error: the sensor reports a healthier machine "
            "than the reference does. Intervals: 95 % percentile over 2000 resamples of the "
            "recordings within each condition, as `sdt compare` gives them for Macro F1."
        ),
        Heading("Zone tables used", 3),
        *_tables_used(agreement),
        Heading("Zone agreement", 3),
        Table(AGREEMENT_HEADER, tuple(agreement_rows(agreement))),
        Heading("Zone confusion (all channels)", 3),
        *_confusions(agreement),
        Heading("Alarms (ISO 20816-1 criterion II)", 3),
        Paragraph(
            "Per machine and channel, the reference's healthy windows set the baseline "
            "(mean V_RMS); ALARM = min(baseline + 0.25 x B/C, 1.25 x B/C) and TRIP = "
            "1.25 x C/D (ISO 20816-1:2016 5.4.1, 5.4.2). The alarm is one bit a node can "
            "send per report: the table says how often each sensor sends the reference's "
            "bit on fault windows, and how often it alarms on healthy windows."
        ),
        _alarms(agreement),
    ]
    return blocks + spectral_blocks(folder, registry, figures_dir, colors)
