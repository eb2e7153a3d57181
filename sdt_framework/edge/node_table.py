"""A :class:`~.node.NodeBudget` as a summary line, column names and text rows.

One layout serves ``sdt budget --sensor`` and the report's "Edge budget"
section, so the two never disagree.
"""

from __future__ import annotations

import math

from .interval import format_interval
from .node import NodeBudget

__all__ = ["format_life", "node_rows", "node_sources", "node_summary"]


def format_life(years: float) -> str:
    """``"8.75"`` years, or ``"> 100"`` (the model is not meant beyond a century)."""
    return "> 100" if math.isinf(years) or years > 100 else f"{years:.2f}"


def node_summary(budget: NodeBudget) -> str:
    """One sentence: which sensor, cell, rate and interval, and the result."""
    cell = budget.battery
    return (
        f"{budget.sensor} on {cell.name} ({cell.capacity_mah:g} mAh, {cell.voltage_v:g} V), one "
        f"report every {format_interval(budget.interval_s)} at {budget.region} {budget.data_rate}: "
        f"{budget.charge_per_report_c * 1e3:.3f} mC = {budget.energy_per_report_j * 1e3:.2f} mJ "
        f"per report, average {budget.average_current_a * 1e6:.2f} uA, battery life "
        f"{format_life(budget.life_years)} years"
    )


def _cell(value: float | None, scale: float, digits: int) -> str:
    return "-" if value is None else f"{value * scale:.{digits}f}"


def node_rows(budget: NodeBudget) -> tuple[list[str], list[list[str]]]:
    """Column names and one row per consumer, then the total."""
    columns = ["consumer", "current mA", "time s", "charge mC", "share %"]
    total = budget.charge_per_report_c
    rows = []
    for stage in budget.stages:
        share = None if stage.charge_c is None or total == 0 else stage.charge_c / total
        rows.append(
            [
                stage.consumer,
                _cell(stage.current_a, 1e3, 4),
                f"{stage.time_s:.4f}",
                "not counted" if stage.charge_c is None else f"{stage.charge_c * 1e3:.4f}",
                _cell(share, 100, 1),
            ]
        )
    rows.append(["total per report", "", "", f"{total * 1e3:.4f}", "100.0"])
    return columns, rows


def node_sources(budget: NodeBudget) -> list[str]:
    """Where each consumer's current and time come from, then the cell and the notes."""
    lines = [f"{stage.consumer}: {stage.source}" for stage in budget.stages]
    cell = budget.battery
    lines.append(f"battery {cell.name}: {cell.source}")
    if cell.self_discharge_source:
        lines.append(f"battery {cell.name} self-discharge: {cell.self_discharge_source}")
    lines += [f"note: {note}" for note in budget.notes]
    return lines
