"""Table 4 of ``sdt benchmark`` in the terminal: one table per machine, mean over ± SD."""

from __future__ import annotations

from typing import Any

from rich.table import Table

from .common import console, print_table

__all__ = ["print_table4"]


def print_table4(results: Any, sensor_order: list[str]) -> None:
    """Table 4 in the terminal: one table per machine, scenario blocks, mean over ± SD."""
    from ..bench import build_table4

    table = build_table4(results, sensor_order)
    if table.empty:
        console.print("No successful runs: nothing to tabulate.")
        return
    for machine in sorted({m for m, _ in table.columns}):
        wanted = [i for i, (m, _) in enumerate(table.columns) if m == machine]
        out = Table(title=f"Macro F1 (mean ± SD), {machine}", title_justify="left")
        out.add_column("scenario")
        out.add_column("sensor")
        for i in wanted:
            out.add_column(table.columns[i][1].upper(), justify="right")
        for block in table.blocks:
            for k, (sensor, row) in enumerate(zip(block.sensors, block.cells, strict=True)):
                cells = [row[i] for i in wanted]
                out.add_row(
                    block.scenario if k == 0 else "",
                    sensor,
                    *("–" if c.mean != c.mean else f"{c.mean:.4f}" + _sd(c.sd) for c in cells),
                    end_section=k == len(block.sensors) - 1,
                )
        print_table(out)


def _sd(sd: float) -> str:
    return "" if sd != sd else f"\n±{sd:.4f}"
