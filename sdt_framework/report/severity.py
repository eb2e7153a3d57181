"""The report's "Severity and alarms" section: ISO zones and alarms, and the field's spectra.

Tables from :mod:`sdt_framework.severity` on the folder's features.parquet
(the V_RMS band each sensor covers when its chain clips it, zone tables used
and why, zone agreement with recording-level intervals, the zone per
condition, zone confusion per machine, criterion II alarms on each sensor's
own baseline: :mod:`.severity_tables`), then the spectral figures
(:mod:`.figures_severity`).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SDTError
from ..severity import (
    NO_VRMS,
    ZONES,
    Agreement,
    assign_tables,
    sensor_bandwidths,
    vrms_bands,
    zone_agreement,
)
from ..specs import MachineSpec
from .document import Block, Heading, Paragraph, Table, literal
from .figures_severity import spectral_blocks
from .load import ResultsFolder
from .machines import folder_machines
from .severity_tables import alarm_table, condition_table

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
                f"(a `zone_table` in its machine spec, `zones = {{ MACHINE = 'TABLE' }}` under "
                f"`[benchmark]` in the config, or `sdt compare --zones MACHINE=TABLE`, grades it)."
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


def folder_agreement(folder: ResultsFolder, registry: Any = None) -> Agreement:
    """The folder's zone and alarm agreement with the reference, computed once.

    The "Severity and alarms" section and the decision table both show it;
    its recording bootstrap is the costly part, so the result (or the
    :class:`SDTError` saying why there is none) is kept on the folder. With a
    ``registry``, the band each sensor's V_RMS covers is checked against its
    chain (added to a kept result that was computed without one). The machines' own
    zone tables come from the folder's machines (:func:`.machines.folder_machines`).
    """
    if folder.agreement is None:
        try:
            folder.agreement = _agreement(folder, folder_machines(folder, registry).specs)
        except SDTError as exc:
            folder.agreement = exc
    if isinstance(folder.agreement, SDTError):
        raise folder.agreement
    if registry is not None and folder.agreement.bands.empty:
        sensors = [folder.agreement.reference, *sorted(folder.agreement.zones["sensor"].unique())]
        bands, warnings = vrms_bands(sensor_bandwidths(sensors, registry.sensor))
        folder.agreement = replace(folder.agreement, bands=bands, warnings=warnings)
    return folder.agreement


def _agreement(folder: ResultsFolder, machines: dict[str, MachineSpec]) -> Agreement:
    features = folder.features
    if features is None or features.empty:
        raise SDTError("features.parquet with V_RMS is missing.")
    if "V_RMS" not in features.columns:
        raise SDTError(NO_VRMS + ".")
    config = folder.config
    assignments = assign_tables(
        sorted(features["machine"].unique()),
        configured=config.zones if config is not None else None,
        where=f"{folder.path / 'config.toml'}: [benchmark] zones",
        window_s=config.window_s if config is not None else None,
        specs=machines,
    )
    seed = config.seed if config is not None else 0
    return zone_agreement(features, folder.reference, assignments, seed=seed)


def _bands(agreement: Agreement) -> list[Block]:
    """The V_RMS band each sensor covers, when one is clipped (or not checked)."""
    if not agreement.warnings:
        return []
    return [Paragraph("V_RMS band: " + "; ".join(literal(w) for w in agreement.warnings) + ".")]


def severity_blocks(
    folder: ResultsFolder, registry: Any, figures_dir: Path, colors: dict[str, str]
) -> list[Block]:
    """The whole section; a note instead of the tables when features.parquet is absent."""
    blocks: list[Block] = [Heading("Severity and alarms", 2)]
    try:
        agreement = folder_agreement(folder, registry)
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not shown: {literal(exc)}")]
    rule = agreement.rule
    blocks += [
        Paragraph(
            "How a condition-monitoring engineer grades the machine: each window's V_RMS "
            "(velocity r.m.s. over 10-1000 Hz, or up to where a sensor's chain stops when "
            "that is lower, mm/s) in ISO zones A (new machine), B (unrestricted long-term "
            "operation), C (limited period), D (damage), by each sensor and by the reference, "
            "windows paired one to one (repetition 0). 'Better zone' is the dangerous error: "
            "the sensor reports a healthier machine than the reference does. Intervals: 95 % "
            "percentile over 2000 resamples of the recordings within each condition, as `sdt "
            "compare` gives them for Macro F1."
        ),
        *_bands(agreement),
        Heading("Zone tables used", 3),
        *_tables_used(agreement),
        Heading("Zone agreement", 3),
        Table(AGREEMENT_HEADER, tuple(agreement_rows(agreement))),
        Heading("Zone per condition", 3),
        condition_table(agreement),
        Heading("Zone confusion (all channels)", 3),
        *_confusions(agreement),
        Heading(f"Alarms (criterion II, {rule.source})", 3),
        Paragraph(
            "Criterion II is relative: each measuring point alarms on a change from its own "
            "baseline. Per machine, channel and sensor, the sensor's own healthy windows set "
            "its baseline (mean V_RMS); its bit is raised above ALARM = min(baseline + "
            f"{rule.alarm_fraction:g} x B/C, {rule.alarm_headroom:g} x B/C) or below baseline "
            f"- {rule.change_fraction:g} x B/C (a decrease is a change too); TRIP = "
            f"{rule.trip_headroom:g} x C/D ({literal(rule.source)}, as transcribed in "
            "docs/severity.md). The reference's bit uses the reference's baseline. The table "
            "says how often each sensor sends the reference's bit on fault windows on its own "
            "baseline and, beside it, on the reference's baseline (a node commissioned with "
            "the reference's figures: there a gain error becomes an alarm disagreement), and "
            "how often it alarms on healthy windows."
        ),
        alarm_table(agreement),
    ]
    return blocks + spectral_blocks(folder, registry, figures_dir, colors)
