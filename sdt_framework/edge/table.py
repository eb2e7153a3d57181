"""An :class:`~.budget.EdgeBudget` as a title, column names and text rows.

One layout serves the terminal (``sdt budget``) and the report's "Edge budget"
section, so the two never disagree.
"""

from __future__ import annotations

from .budget import EdgeBudget
from .interval import format_interval

__all__ = ["budget_rows", "budget_summary"]


def budget_summary(budget: EdgeBudget) -> str:
    """One sentence: what a report holds, how often it goes, over which plan and radio."""
    dtypes = "/".join(budget.dtypes)
    duty = "no duty cycle" if budget.duty_cycle is None else f"duty cycle {budget.duty_cycle:.0%}"
    radio = budget.radio
    return (
        f"{budget.feature_set}: {budget.n_features} features x {dtypes} = "
        f"{budget.bytes_per_window_per_axis} B/axis x {budget.axes} "
        f"{'axis' if budget.axes == 1 else 'axes'} = "
        f"{budget.app_payload_bytes} B per report (+{budget.overhead_bytes} B LoRaWAN per "
        f"uplink), every {format_interval(budget.interval_s)} "
        f"({budget.reports_per_day:g} reports/day); {budget.region}, {duty}; radio "
        f"{radio.name} ({radio.tx_current_a * 1e3:g} mA at {radio.supply_v:g} V, transmit only)"
    )


def _flag(value: bool | None) -> str:
    return "-" if value is None else ("yes" if value else "NO")


def budget_rows(budget: EdgeBudget) -> tuple[list[str], list[list[str]]]:
    """Column names and one row of text per data rate."""
    has_duty = budget.duty_cycle is not None
    has_dwell = any(row.dwell_ok is not None for row in budget.rows)
    columns = ["DR", "SF/kHz", "max B", "fits", "uplinks", "ToA ms"]
    if has_duty:
        columns += ["min interval s", "duty ok"]
    if has_dwell:
        columns += ["dwell ok"]
    columns += ["ToA s/day", "TX mJ", "TX J/day"]
    rows = []
    for row in budget.rows:
        cells = [
            row.data_rate,
            row.modulation.removesuffix(" kHz"),
            str(row.max_app_payload),
            "yes" if row.fits else "no",
            str(row.messages_per_report),
            f"{row.time_on_air_s * 1e3:.1f}",
        ]
        if has_duty:
            cells += [f"{row.min_interval_s:.1f}", _flag(row.duty_cycle_ok)]
        if has_dwell:
            cells += [_flag(row.dwell_ok)]
        cells += [
            f"{row.airtime_per_day_s:.1f}",
            f"{row.energy_per_report_j * 1e3:.2f}",
            f"{row.energy_per_day_j:.2f}",
        ]
        rows.append(cells)
    return columns, rows
