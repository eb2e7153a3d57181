"""A :class:`~.node.NodeBudget` as a summary line, column names and text rows.

One layout serves ``sdt budget --sensor`` and the report's "Edge budget"
section, so the two never disagree.
"""

from __future__ import annotations

import math

from .interval import format_interval
from .node import NodeBudget

__all__ = ["format_life", "life_words", "node_rows", "node_sources", "node_summary"]


def format_life(years: float) -> str:
    """``"8.75"`` years, or ``"> 100"`` (the model is not meant beyond a century)."""
    return "> 100" if math.isinf(years) or years > 100 else f"{years:.2f}"


def life_words(budget: NodeBudget) -> str:
    """``"6.44 years (an estimate under typical figures)"``, or the life at its named cap."""
    years = f"{format_life(budget.life_years)} years"
    if budget.life_capped:
        alone = budget.uncapped_life_years
        more = "no end" if math.isinf(alone) else f"{alone:.1f} years"
        return (
            f"{years}, capped at the {budget.battery.name} cell's rated shelf life (the drain "
            f"alone would give {more})"
        )
    return f"{years} (an estimate under typical figures; see the notes)"


def node_summary(budget: NodeBudget) -> str:
    """One sentence: which sensor, cell, radio, rate and interval, and the result."""
    cell = budget.battery
    uplinks = "" if budget.uplinks == 1 else f" in {budget.uplinks} uplinks"
    return (
        f"{budget.sensor} on {cell.name} ({budget.capacity_mah:.0f} mAh at this drain, "
        f"{cell.voltage_v:g} V), one report every {format_interval(budget.interval_s)} at "
        f"{budget.region} {budget.data_rate}{uplinks} on {budget.radio}: "
        f"{budget.charge_per_report_c * 1e3:.3f} mC = {budget.energy_per_report_j * 1e3:.2f} mJ "
        f"per report, average {budget.average_current_a * 1e6:.2f} uA, battery life "
        f"{life_words(budget)}"
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
    lines.append(
        f"battery {cell.name} self-discharge {cell.self_discharge_per_year:.2%}/year: "
        f"{cell.self_discharge_source or 'user setting'}"
    )
    lines.append(
        f"battery {cell.name} shelf life {cell.shelf_life_years:g} years: "
        f"{cell.shelf_life_source or 'user setting'}"
    )
    lines += [f"note: {note}" for note in budget.notes]
    return lines
