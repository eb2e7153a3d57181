"""The paper's Table 4 as data, built once from the results and rendered three ways.

:func:`build_table4` turns the tidy results into a :class:`Table4`: machine x
classifier columns, one block per scenario (paper order A, B, C), one row per
sensor label (a sensor, ``TRAIN -> TEST`` for a transfer, ``S @ NODE`` for a
node) holding mean, SD (sample SD, ddof=1) and count of Macro F1 per column,
with the best mean of each column in each block marked. It is rendered as
Markdown here (``table4.md``, :func:`table4_markdown`), for the terminal by
``sdt benchmark`` and as a document table (Markdown and HTML) by the report;
none of them parses another's text.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from .results import scenario_rank, scenario_title

__all__ = ["NOTE", "Cell", "Table4", "build_table4", "table4", "table4_blocks", "table4_markdown"]

NOTE = "Macro F1, mean ± SD (sample SD over repetitions); best mean per column in bold."
EMPTY = "_No successful runs: nothing to tabulate._"


def table4(results: pd.DataFrame) -> pd.DataFrame:
    """Mean and SD of Macro F1 per (scenario, sensor) x (machine, classifier).

    Returns a frame indexed by (scenario, sensor) with a column MultiIndex
    (machine, classifier, stat) where stat is "mean", "sd" or "n".
    """
    ok = results[results["status"] == "ok"]
    grouped = ok.groupby(["scenario", "sensor", "machine", "classifier"])["macro_f1"]
    stats = pd.DataFrame({"mean": grouped.mean(), "sd": grouped.std(ddof=1), "n": grouped.count()})
    wide = stats.unstack(["machine", "classifier"])
    wide = wide.reorder_levels([1, 2, 0], axis=1).sort_index(axis=1)
    order = {
        s: i for i, s in enumerate(sorted(set(stats.index.get_level_values(0)), key=scenario_rank))
    }
    return wide.sort_index(key=lambda idx: idx.map(order) if idx.name == "scenario" else idx)


def table4_blocks(
    wide: pd.DataFrame, sensor_order: Sequence[str] = ()
) -> Iterator[tuple[str, pd.DataFrame, list[str]]]:
    """(scenario, its block of ``table4(...)``, sensors in display order) per scenario.

    Scenarios come in the paper's order (A, B, C), then speed transfers
    (:func:`~.results.scenario_rank`); sensors in ``sensor_order``
    first, then any others in the block. Table 4 and the report's deltas walk
    the pivot through this one function.
    """
    present = set(wide.index.get_level_values(0))
    for scenario in sorted(present, key=scenario_rank):
        block = wide.loc[scenario]
        sensors = [s for s in sensor_order if s in block.index]
        sensors += [s for s in block.index if s not in sensors]
        yield scenario, block, sensors


@dataclass(frozen=True)
class Cell:
    """Macro F1 of one sensor in one (machine, classifier) column."""

    mean: float
    sd: float
    n: float
    best: bool  # the best mean of its column in its scenario block

    def text(self) -> str:
        """``mean ± sd`` to 4 decimals; the mean alone from one run; an en dash if none."""
        if np.isnan(self.mean):
            return "–"
        if self.n < 2 or np.isnan(self.sd):
            return f"{self.mean:.4f}"
        return f"{self.mean:.4f} ± {self.sd:.4f}"

    def inline(self) -> str:
        """:meth:`text`, in ``**bold**`` if it is the best of its column."""
        return f"**{self.text()}**" if self.best else self.text()


@dataclass(frozen=True)
class Block:
    """One scenario: its sensors in display order, and their cells in column order."""

    scenario: str
    sensors: tuple[str, ...]
    cells: tuple[tuple[Cell, ...], ...]

    @property
    def title(self) -> str:
        """The paper's title of the scenario ("Experiment A. Forward extrapolation"), or a
        speed transfer's ("Speed transfer: trained at 100, tested at 75")."""
        return scenario_title(self.scenario)


@dataclass(frozen=True)
class Table4:
    """Table 4: (machine, classifier) columns and one block per scenario."""

    columns: tuple[tuple[str, str], ...]
    blocks: tuple[Block, ...]

    @property
    def empty(self) -> bool:
        """No successful run: nothing to tabulate."""
        return not self.blocks

    @property
    def header(self) -> tuple[str, ...]:
        """``Sensor`` and one ``machine CLASSIFIER`` per column."""
        return ("Sensor", *(f"{m} {c.upper()}" for m, c in self.columns))

    def rows(self) -> Iterator[tuple[str, ...]]:
        """Inline-text rows: a ``**title**`` row opening each block, then its sensors."""
        for block in self.blocks:
            yield (f"**{block.title}**",) + ("",) * len(self.columns)
            for sensor, cells in zip(block.sensors, block.cells, strict=True):
                yield (sensor, *(cell.inline() for cell in cells))


def build_table4(results: pd.DataFrame, sensor_order: Sequence[str] = ()) -> Table4:
    """Table 4 of the tidy ``results`` (successful runs), sensors in ``sensor_order`` first."""
    wide = table4(results)
    if wide.empty:
        return Table4((), ())
    columns = tuple(sorted({(m, c) for m, c, _ in wide.columns}))
    blocks = []
    for scenario, block, sensors in table4_blocks(wide, sensor_order):
        best = {col: block[(*col, "mean")].max() for col in columns}
        cells = []
        for sensor in sensors:
            row = []
            for col in columns:
                mean, sd, n = (float(block.loc[sensor, (*col, s)]) for s in ("mean", "sd", "n"))
                row.append(Cell(mean, sd, n, not np.isnan(mean) and mean == best[col]))
            cells.append(tuple(row))
        blocks.append(Block(scenario, tuple(sensors), tuple(cells)))
    return Table4(columns, tuple(blocks))


def table4_markdown(table: Table4) -> str:
    """The text of ``table4.md``: a pipe table, a bold row per scenario, then :data:`NOTE`."""
    if table.empty:
        return EMPTY + "\n"
    n = len(table.columns)
    lines = ["| " + " | ".join(table.header) + " |", "|---|" + "---|" * n]
    for block in table.blocks:
        lines.append(f"| **{block.title}** |" + " |" * n)
        for sensor, cells in zip(block.sensors, block.cells, strict=True):
            lines.append("| " + " | ".join((sensor, *(cell.inline() for cell in cells))) + " |")
    return "\n".join(lines) + "\n" + "\n" + NOTE + "\n"
