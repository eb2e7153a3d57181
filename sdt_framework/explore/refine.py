"""Adaptive refinement along ordered axes: bisection between the last level that fails and the
first that passes, instead of the full grid.

The minimum specification of a parameter reads one line of the grid: the
points whose other parameters sit at the base sensor's values
(:func:`~sdt_framework.explore.minspec.min_spec`). Along that line the levels
are ordered from least to most demanding (by magnitude where lower is harder,
``-x`` and ``+x`` forming one group, as in ``min_spec``). The answer of a cell
(machine, scenario, classifier) is the group just above the highest group
that fails. With only some groups evaluated, the cell's bracket is ``lo`` =
the highest evaluated group that fails (-1: none) and ``hi`` = the lowest
evaluated group above it (all of which pass; ``n``: none). The cell is
resolved when ``hi == lo + 1``; otherwise the group halfway between is run
next. A round runs the halfway groups of every unresolved cell at once.

The first round runs, per line, the groups where the screen (cheap classifiers,
one repetition) puts the answer of some cell: the highest group failing on the
screen and the one above it. The full protocol then bisects from there, so
where the screen and the full protocol agree, one round settles the answer.

It assumes the full-protocol curve of a cell does not fail again above a
level that passes: the screen is run on every level, and the levels it finds
failing are the ones the first round confirms. These functions are pure.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from .effects import CELL
from .objectives import diagnosis_meets

__all__ = ["Line", "bracket", "lines", "next_groups", "screen_groups"]


@dataclass(frozen=True)
class Line:
    """A parameter's line through the base: point names grouped by level, least demanding first."""

    field: str
    levels: tuple[float, ...]
    groups: tuple[tuple[str, ...], ...]


def lines(
    points: pd.DataFrame,
    fields: Sequence[str],
    base_values: Mapping[str, float],
    demand: Mapping[str, str],
) -> dict[str, Line]:
    """The line of every field: ``points`` has a ``point`` column and one column per field."""
    out = {}
    for field in fields:
        at_base = np.ones(len(points), dtype=bool)
        for other in fields:
            if other != field:
                at_base &= np.isclose(points[other].to_numpy(float), float(base_values[other]))
        line = points[at_base]
        values = line[field].to_numpy(float)
        higher = demand[field] == "higher"
        keys = values if higher else np.abs(values)
        unique = np.unique(keys)
        order = unique if higher else unique[::-1]  # least demanding first
        groups = tuple(tuple(line["point"][np.isclose(keys, k)]) for k in order)
        out[field] = Line(field, tuple(float(k) for k in order), groups)
    return out


def bracket(meets: Sequence[bool | None]) -> tuple[int, int]:
    """``(lo, hi)`` of one cell's groups (None: not evaluated); resolved when ``hi == lo + 1``."""
    lo = max((i for i, m in enumerate(meets) if m is False), default=-1)
    hi = next((i for i in range(lo + 1, len(meets)) if meets[i]), len(meets))
    return lo, hi


def _group_meets(line: Line, verdicts: pd.DataFrame) -> dict[tuple, list[bool | None]]:
    """Per cell, each group's verdict: True/False when all its points were evaluated."""
    by_cell: dict[tuple, list[bool | None]] = {}
    for cell, part in verdicts.groupby(CELL, sort=True):
        meets = diagnosis_meets(part).set_axis(part["point"])  # bisect what demand helps
        row: list[bool | None] = []
        for group in line.groups:
            if all(p in meets.index for p in group):
                row.append(bool(meets.loc[list(group)].all()))
            else:
                row.append(None)
        by_cell[cell] = row
    return by_cell


def next_groups(line: Line, verdicts: pd.DataFrame) -> set[int]:
    """The groups to run next: the halfway group of every unresolved cell."""
    out = set()
    for meets in _group_meets(line, verdicts).values():
        lo, hi = bracket(meets)
        if hi > lo + 1:
            out.add((lo + hi) // 2)
    return out


def screen_groups(line: Line, verdicts: pd.DataFrame) -> set[int]:
    """Where the screen puts each cell's answer: its highest failing group and the one above."""
    out = set()
    for meets in _group_meets(line, verdicts).values():
        lo, _ = bracket([bool(m) for m in meets])  # the screen ran every group
        out |= {i for i in (lo, lo + 1) if 0 <= i < len(line.groups)}
    return out
