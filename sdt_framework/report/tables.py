"""The report's tables as data: Table 4, deltas to the reference, allocation, failures.

Table 4 is the one :class:`~sdt_framework.bench.table4.Table4` built from the
results (``table4.md`` is its Markdown); the delta table is built from the same
:func:`~sdt_framework.bench.table4.table4` pivot so both always agree.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..bench.results import scenario_title
from ..bench.table4 import EMPTY, NOTE, build_table4, table4, table4_blocks
from .document import Table, literal

__all__ = ["allocation_table", "delta_table", "failed_table", "table4_table"]


def table4_table(results: pd.DataFrame, sensors: list[str]) -> Table:
    """Paper Table 4: mean ± SD Macro F1 per scenario/sensor x machine/classifier."""
    table = build_table4(results, sensors)
    if table.empty:
        return Table(("",), ((EMPTY,),))
    rows: list[tuple[str, ...]] = []
    for block in table.blocks:  # Table4.rows(), with the sensors' names as literal text
        rows.append((f"**{literal(block.title)}**",) + ("",) * len(table.columns))
        for sensor, cells in zip(block.sensors, block.cells, strict=True):
            rows.append((literal(sensor), *(cell.inline() for cell in cells)))
    return Table(tuple(map(literal, table.header)), tuple(rows), NOTE)


def delta_table(results: pd.DataFrame, sensors: list[str], reference: str) -> Table | None:
    """Mean Macro F1 of each sensor minus the reference's, per cell.

    Parameters
    ----------
    results
        The tidy results table (failed runs are ignored).
    sensors
        Sensor order for the rows.
    reference
        The reference sensor; None is returned when it has no successful run.

    Returns
    -------
    Table or None
        Scenario blocks of one row per non-reference sensor; the largest delta
        of each column within a block is bold (the sensor that loses least).
    """
    wide = table4(results)
    if wide.empty or reference not in wide.index.get_level_values("sensor"):
        return None
    columns = sorted({(m, c) for m, c, _ in wide.columns})
    rows: list[tuple[str, ...]] = []
    for scenario, block, ordered in table4_blocks(wide, sensors):
        if reference not in block.index:
            continue
        means = block.xs("mean", axis=1, level=2)
        delta = means.drop(index=reference) - means.loc[reference]
        order = [s for s in ordered if s != reference]
        if not order:
            continue
        rows.append((f"**{literal(scenario_title(scenario))}**",) + ("",) * len(columns))
        best = {col: delta[col].max() for col in columns}
        for sensor in order:
            cells = []
            for col in columns:
                value = delta.loc[sensor, col]
                text = "–" if np.isnan(value) else f"{value:+.4f}"
                bold = not np.isnan(value) and value == best[col]
                cells.append(f"**{text}**" if bold else text)
            rows.append((literal(sensor), *cells))
    header = ("Sensor", *(literal(f"{m} {c.upper()}") for m, c in columns))
    note = (
        f"Mean Macro F1 of the sensor minus that of the reference ({literal(reference)}) for the "
        "same scenario, machine and classifier; negative = the sensor costs performance. "
        "Largest delta per column and scenario in bold."
    )
    return Table(header, tuple(rows), note)


def _runs(names: pd.Series, limit: int = 6) -> str:
    runs = sorted(set(names))
    shown = ", ".join(map(literal, runs[:limit]))
    return f"{len(runs)}: {shown}" + (f", … (+{len(runs) - limit})" if len(runs) > limit else "")


def allocation_table(allocation: pd.DataFrame) -> Table:
    """Per machine and scenario: the number of train and test runs and their names (shortened)."""
    rows = []
    for (machine, scenario), part in allocation.groupby(["machine", "scenario"], sort=True):
        rows.append(
            (
                literal(machine),
                literal(scenario),
                _runs(part.loc[part["side"] == "train", "run"]),
                _runs(part.loc[part["side"] == "test", "run"]),
            )
        )
    note = "A run is one condition directory with all its channels; full table: allocation.csv."
    return Table(("Machine", "Scenario", "Train runs", "Test runs"), tuple(rows), note)


def failed_table(failed: pd.DataFrame, limit: int = 50) -> Table:
    """Failed runs with the first line of their error (at most ``limit`` rows)."""
    keys = ["machine", "scenario", "sensor", "classifier", "repeat"]
    rows = []
    for _, run in failed.head(limit).iterrows():
        error = str(run.get("error") or "no message").strip().splitlines() or ["no message"]
        rows.append((*(literal(run[k]) for k in keys), literal(error[0][:200])))
    more = f"; first {limit} shown" if len(failed) > limit else ""
    note = f"{len(failed)} failed run(s){more}"
    return Table((*keys, "error"), tuple(rows), note + "; full messages in results.csv.")
