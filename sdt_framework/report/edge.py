"""The report's "Edge budget" section: what sending the benchmark's features costs a node.

For the feature set (and feature dtype) of the results folder's configuration:
a triaxial node reporting one window's features every 10 minutes, over every
LoRa data rate of EU868 and US915, as ``sdt budget`` prints it (formulas and
sources in docs/edge.md).
"""

from __future__ import annotations

from typing import Any

from ..edge import edge_budget
from ..edge.table import budget_rows, budget_summary
from ..errors import SDTError
from ..features import resolve_feature_set
from .document import Block, Heading, Paragraph, Table, literal
from .load import ResultsFolder

__all__ = ["AXES", "INTERVAL_S", "REGIONS", "edge_blocks"]

AXES = 3
INTERVAL_S = 600.0
REGIONS = ("EU868", "US915")


def _fits(budget) -> str:
    names = [row.data_rate for row in budget.fitting()]
    return ", ".join(names) if names else "no data rate"


def edge_blocks(folder: ResultsFolder, registry: Any) -> list[Block]:
    """Heading, explanation and one table per region; a note if the set cannot be resolved."""
    blocks: list[Block] = [Heading("Edge budget", 2)]
    config = folder.config
    if config is None:
        return [*blocks, Paragraph("Not shown: config.toml is missing or invalid.")]
    try:
        spec = resolve_feature_set(registry, config.features)
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not shown: {literal(exc)}")]
    dtype = config.feature_dtype
    blocks.append(
        Paragraph(
            f"What a battery node would spend to send this benchmark's features: one report "
            f"(one window's feature vector on each of {AXES} axes) every "
            f"{INTERVAL_S / 60:g} minutes over LoRaWAN, per data rate. Time on air from the "
            f"Semtech SX127x formula, payload limits from the LoRaWAN Regional Parameters, "
            f"transmit energy only (`sdt budget --help`, docs/edge.md). The payload depends "
            f"on the feature set and its dtype, not on the sensor."
        )
    )
    budgets = {
        region: edge_budget(spec, axes=AXES, interval_s=INTERVAL_S, region=region, dtype=dtype)
        for region in REGIONS
    }
    for region, budget in budgets.items():
        columns, rows = budget_rows(budget)
        blocks += [
            Heading(region, 3),
            Table(
                tuple(map(literal, columns)),
                tuple(tuple(map(literal, r)) for r in rows),
                literal(budget_summary(budget)),
            ),
        ]
    current = budgets[REGIONS[0]]
    other = "float32" if current.dtypes == ("float16",) else "float16"
    alt = edge_budget(spec, axes=AXES, interval_s=INTERVAL_S, region=REGIONS[0], dtype=other)
    blocks.append(
        Paragraph(
            f"Sent as {other}, a report would be {alt.app_payload_bytes} B instead of "
            f"{current.app_payload_bytes} B and fit one {REGIONS[0]} uplink at {_fits(alt)} "
            f"(now: {_fits(current)}). `sdt benchmark --feature-dtype {other}` measures what "
            f"that rounding costs the classifiers."
        )
    )
    return blocks
