"""The report's opening decision table: one row per candidate sensor.

What a designer weighs: the Macro F1 lost against the reference with the
verdict's label (:mod:`sdt_framework.verdict`, the same numbers as the
Verdict section), the part's indicative price, its supply current while
measuring, the payload of one report, and the node's battery life on 2xAA
cells (:mod:`.node_edge`), and its zone agreement with the reference (the
"Severity and alarms" section's figure). A figure that is not on record says so.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..edge import report_bytes
from ..errors import SDTError
from ..features import resolve_feature_set
from .document import Block, Heading, Paragraph, Table, code, literal
from .load import ResultsFolder
from .node_edge import BATTERY, life_cell, node_budgets
from .severity import folder_agreement
from .verdict import folder_comparison, missing_reference_note

__all__ = ["decision_blocks"]


def _losses(folder: ResultsFolder, margin: float) -> dict[str, str]:
    if missing_reference_note(folder) is not None:
        return {}
    try:
        comparison = folder_comparison(folder, margin)
    except Exception:  # the Verdict section reports why; the table says "-"
        return {}
    overall = comparison.table[comparison.table["level"] == "overall"]
    out = {}
    for row in overall.itertuples():
        low, high = row.ci_low, row.ci_high
        interval = "" if np.isnan(low) else f" [{low:+.3f}, {high:+.3f}]"
        out[row.candidate] = f"{row.delta:+.3f}{interval} **{literal(row.label)}**"
    return out


def _price(registry: Any, name: str) -> str:
    base = name.split("[", 1)[0]  # a part's name without its mode
    for candidate, label in ((base, ""), (f"{base}-ds", f" (part {base}-ds)")):
        try:
            part = registry.part(candidate)
        except SDTError:
            continue
        if part.price is None:
            searched = part.no_price
            when = "" if searched is None else f" (searched {literal(searched.date)})"
            return "no public price" + when
        p = part.price
        return literal(f"{p.amount:g} {p.currency}{label}; {p.source}, {p.date}")
    return "no public price"


def _current(registry: Any, name: str) -> str:
    try:
        supply = registry.sensor(name).supply
    except SDTError:
        return "-"
    if supply is None or supply.measure_ua.value is None:
        return "not on record"
    return f"{supply.measure_ua.value:g} uA"


def _zones(folder: ResultsFolder, registry: Any) -> dict[str, str]:
    """Per sensor: its share of windows in the reference's ISO zone, per machine.

    The "Severity and alarms" section's figure (:func:`.severity.folder_agreement`,
    the same as ``sdt compare``'s "same zone"): each machine's share over all its
    channels (the only channel's, when there is one), "Motor-4 91.2 %; ...".
    Empty when it cannot be computed (that section says why).
    """
    try:
        zones = folder_agreement(folder, registry).zones
    except SDTError:
        return {}
    pooled = zones["channel"] == "all"
    has_pooled = pooled.groupby([zones["machine"], zones["sensor"]]).transform("any")
    keep = zones[pooled | ~has_pooled]  # one channel: no "all" row, its own row
    out: dict[str, list[str]] = {}
    for r in keep.sort_values(["sensor", "machine"]).itertuples():
        out.setdefault(r.sensor, []).append(f"{literal(r.machine)} {100 * r.share_same:.1f} %")
    return {sensor: "; ".join(parts) for sensor, parts in out.items()}


def decision_blocks(folder: ResultsFolder, registry: Any, margin: float = 0.02) -> list[Block]:
    """Heading, how to read it and the table; a sentence when it cannot be drawn."""
    blocks: list[Block] = [Heading("Decision table", 2)]
    config = folder.config
    if config is None:
        return [*blocks, Paragraph("Not shown: config.toml is missing or invalid.")]
    try:
        spec = resolve_feature_set(registry, config.features)
        payload = report_bytes(spec, 3, config.feature_dtype)
        lives = node_budgets(folder, registry)
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not shown: {literal(exc)}")]
    losses = _losses(folder, margin)
    zones = _zones(folder, registry)
    rows = tuple(
        (
            literal(name),
            losses.get(name, "-"),
            _price(registry, name),
            _current(registry, name),
            f"{payload} B",
            life_cell(lives.get(name)),
            zones.get(name, "-"),
        )
        for name in folder.sensors
        if name != folder.reference
    )
    blocks.append(
        Paragraph(
            f"One row per candidate. Δ Macro F1 against the reference {code(folder.reference)} "
            f"over all runs, with its 95 % interval and the verdict at ±{margin:g} (see "
            f"Verdict); indicative unit price with its source and date where one is public; "
            f"supply current while measuring (datasheet); application payload of one report "
            f"(3 axes); battery life of the node on {BATTERY}, one report every 10 minutes "
            f"(Edge budget, node energy); share of windows graded in the reference's ISO "
            f"zone per machine, over all channels (Severity and alarms; '-' where it "
            f"cannot be computed)."
        )
    )
    header = (
        "sensor",
        "Δ Macro F1, verdict",
        "price",
        "supply current",
        "payload",
        "life",
        "zone agreement",
    )
    blocks.append(Table(header, rows))
    return blocks
