"""The report's node budget: charge per report by consumer and battery life, per sensor.

For every benchmarked sensor (the reference included when it has supply
figures): the table ``sdt budget --sensor NAME --battery 2xAA`` prints, for
the benchmark's feature set, a triaxial node reporting every 10 minutes in
EU868 (docs/edge.md). A sensor without a measuring current on record gets a
sentence saying so instead of a made-up table.
"""

from __future__ import annotations

from typing import Any

from ..edge.cells import cell
from ..edge.node import NodeBudget, NodeSettings, node_budget
from ..edge.node_table import format_life, node_rows, node_summary
from ..errors import SDTError
from ..features import resolve_feature_set
from .document import Block, Heading, Items, Paragraph, Table, literal
from .load import ResultsFolder

__all__ = ["BATTERY", "node_blocks", "node_budgets"]

BATTERY = "2xAA"


def node_budgets(folder: ResultsFolder, registry: Any) -> dict[str, NodeBudget | str]:
    """Each benchmarked sensor's node budget, or the sentence why there is none."""
    config = folder.config
    if config is None:
        return {}
    spec = resolve_feature_set(registry, config.features)
    if config.feature_dtype is not None:
        spec = spec.with_dtype(config.feature_dtype)
    settings = NodeSettings(window_s=config.window_s, axes=3)
    out: dict[str, NodeBudget | str] = {}
    for name in folder.sensors:
        try:
            out[name] = node_budget(registry.sensor(name), spec, cell(BATTERY), settings)
        except SDTError as exc:
            out[name] = str(exc)
    return out


def node_blocks(folder: ResultsFolder, registry: Any) -> list[Block]:
    """Heading, how to read it, then one table per sensor (or why not)."""
    blocks: list[Block] = [Heading("Node energy and battery life", 3)]
    try:
        budgets = node_budgets(folder, registry)
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not shown: {literal(exc)}")]
    if not budgets:
        return [*blocks, Paragraph("Not shown: config.toml is missing or invalid.")]
    blocks.append(
        Paragraph(
            f"The whole node per report, one stage per consumer, on {BATTERY} cells: the "
            f"accelerometer measuring one window (and its turn-on time) and in standby, the "
            f"microcontroller computing the features, the LoRaWAN uplink and its RX1/RX2 "
            f"windows, and sleep; each figure's source is in `sdt budget --sensor NAME` and "
            f"docs/edge.md. A figure the sources lack is listed as not counted."
        )
    )
    for name, budget in budgets.items():
        blocks.append(Heading(literal(name), 4))
        if isinstance(budget, str):
            blocks.append(Paragraph(f"Not computed: {literal(budget)}"))
            continue
        columns, rows = node_rows(budget)
        cells = tuple(tuple(map(literal, r)) for r in rows)
        summary = literal(node_summary(budget))
        blocks.append(Table(tuple(map(literal, columns)), cells, summary))
        if budget.notes:
            blocks.append(Items(tuple(map(literal, budget.notes))))
    return blocks


def life_cell(budget: NodeBudget | str | None) -> str:
    """Battery life for the decision table: years, or why not."""
    if budget is None or isinstance(budget, str):
        return "no supply figure"
    return f"{format_life(budget.life_years)} y"
