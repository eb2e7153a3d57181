"""Adaptive refinement (bisection along ordered axes) against the answer of the full grid.

The oracle is independent of the code under test: a cell meets at a level
when a known per-cell threshold index is reached (a monotone curve), so the
exhaustive answer is that index, and the refinement must find it from the
groups it chose to evaluate, whatever the screen guessed.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pandas as pd
import pytest

from sdt_framework.explore.refine import bracket, lines, next_groups, screen_groups


def _verdicts(line_points, evaluated, first_pass):
    """Verdict rows for the evaluated points: cell c meets at group i when i >= first_pass[c]."""
    rows = []
    for cell, start in first_pass.items():
        for i, group in enumerate(line_points):
            for point in group:
                if point in evaluated:
                    rows.append(
                        {
                            "point": point,
                            "machine": cell,
                            "scenario": "forward",
                            "classifier": "lr",
                            "meets": i >= start,
                        }
                    )
    return pd.DataFrame(rows, columns=["point", "machine", "scenario", "classifier", "meets"])


def _one_line(n):
    rates = 100.0 * 2.0 ** np.arange(n)
    points = pd.DataFrame({"point": [f"p{i}" for i in range(n)], "rate": rates})
    return lines(points, ["rate"], {"rate": 100.0}, {"rate": "higher"})["rate"]


def _refine(line, first_pass, screen_first_pass):
    """The refinement loop as adaptive.py runs it, on the oracle; returns answers and cost."""
    everything = {p for g in line.groups for p in g}
    todo = screen_groups(line, _verdicts(line.groups, everything, screen_first_pass))
    evaluated: set[str] = set()
    rounds = 0
    while new := {p for g in todo for p in line.groups[g]} - evaluated:
        evaluated |= new
        rounds += 1
        todo = next_groups(line, _verdicts(line.groups, evaluated, first_pass))
    judged = _verdicts(line.groups, evaluated, first_pass)
    answers = {}
    for cell, part in judged.groupby("machine"):
        meets = part.set_index("point")["meets"]
        row = [bool(meets[g[0]]) if g[0] in meets.index else None for g in line.groups]
        answers[cell] = bracket(row)
    return answers, evaluated, rounds


def test_lines_order_levels_least_demanding_first_and_group_magnitudes():
    points = pd.DataFrame(
        {
            "point": ["a", "b", "c", "d", "e"],
            "nsd": [25.0, 90.0, 290.0, 90.0, 290.0],
            "rate": [3200.0, 3200.0, 3200.0, 1600.0, 1600.0],
            "err": [0.0, 0.0, 0.0, 0.0, 0.0],
        }
    )
    base = {"nsd": 290.0, "rate": 3200.0, "err": 0.0}
    demand = {"nsd": "lower", "rate": "higher", "err": "lower"}
    out = lines(points, ["nsd", "rate", "err"], base, demand)
    assert out["nsd"].levels == (290.0, 90.0, 25.0)  # noisier is less demanding
    assert out["nsd"].groups == (("c",), ("b",), ("a",))
    assert out["rate"].groups == (("e",), ("c",))
    signed = pd.DataFrame({"point": ["m", "z", "p"], "err": [-0.5, 0.0, 0.5]})
    line = lines(signed, ["err"], {"err": 0.0}, {"err": "lower"})["err"]
    assert line.levels == (0.5, 0.0) and line.groups == (("m", "p"), ("z",))


@pytest.mark.parametrize("n", [1, 2, 3, 4, 7, 16])
def test_refinement_finds_the_exhaustive_answer_for_every_threshold_and_screen_guess(n):
    line = _one_line(n)
    # every cell's true first passing group (n: no level passes), screens right and wrong
    for truth, guess in itertools.product(range(n + 1), repeat=2):
        answers, _, _ = _refine(line, {"m": truth}, {"m": guess})
        lo, hi = answers["m"]
        assert hi == lo + 1 and hi == truth, (n, truth, guess, answers)


def test_many_cells_resolve_together_and_a_right_screen_needs_one_round():
    line = _one_line(16)
    rng = np.random.default_rng(3)
    truth = {f"c{i}": int(t) for i, t in enumerate(rng.integers(0, 17, 6))}
    answers, evaluated, rounds = _refine(line, truth, truth)
    assert {c: hi for c, (_, hi) in answers.items()} == truth
    assert rounds == 1  # the screen's brackets are the answer's: confirmed, nothing more
    assert len(evaluated) <= 2 * len(truth) < 16


def test_bisection_from_a_wrong_screen_costs_a_logarithm_of_the_levels():
    n = 64
    line = _one_line(n)
    for truth in (0, 1, 17, 40, 63, 64):
        _, evaluated, rounds = _refine(line, {"m": truth}, {"m": 0 if truth > 32 else n})
        assert rounds <= 2 + math.ceil(math.log2(n + 1))
        assert len(evaluated) <= 2 + math.ceil(math.log2(n + 1)) + 1 < n


def test_bracket_reads_unevaluated_groups_as_unknown():
    assert bracket([None, None, None]) == (-1, 3)
    assert bracket([False, None, True, None]) == (0, 2)
    assert bracket([True, False, None, True]) == (1, 3)  # a pass below a fail does not count
    assert bracket([False, False]) == (1, 2)
    assert bracket([True, None]) == (-1, 0)
