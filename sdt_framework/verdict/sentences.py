"""The verdict in plain sentences, generated from a :class:`~.compare.Comparison`.

One finding per verdict group (machine and scenario): the best sensor with
its mean Macro F1, then per candidate the label over the group's cells and
which cells (classifiers) are equivalent, worse, better or inconclusive, each
with Δ and its 95 % interval, the inconclusive ones with their reason. Then
one finding per candidate over all cells, and one for the Friedman/Nemenyi
ranking. Every number in a sentence is a number of the comparison table.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from .compare import Comparison

__all__ = ["Finding", "fmt_delta", "verdict"]


@dataclass(frozen=True)
class Finding:
    """One verdict paragraph: what it is about (``scope``) and what it says."""

    scope: str
    text: str


def fmt_delta(row: pd.Series | object) -> str:
    """``Δ -0.045 [-0.050, -0.040]; recording CI [-0.070, -0.018]``: Δ and both its intervals.

    A label other than inconclusive needs both intervals to agree
    (:func:`.equivalence.combine`), so both are printed wherever a label is:
    the repetition interval alone can lie wholly beyond the margin beside an
    "inconclusive" that the recording interval decided.
    """
    delta, low, high = (getattr(row, k) for k in ("delta", "ci_low", "ci_high"))
    rec_low, rec_high = (getattr(row, k, np.nan) for k in ("rec_ci_low", "rec_ci_high"))
    rec = "" if np.isnan(rec_low) else f"; recording CI [{rec_low:+.3f}, {rec_high:+.3f}]"
    if np.isnan(low):
        return f"Δ {delta:+.3f}, no interval{rec}"
    return f"Δ {delta:+.3f} [{low:+.3f}, {high:+.3f}]{rec}"


def _short(reason: str) -> str:
    return reason.split(":")[0] if reason else ""


def _scope(comparison: Comparison, key: tuple) -> str:
    table = comparison.table
    shown = [
        str(v)
        for c, v in zip(comparison.groups, key, strict=True)
        if table.loc[table["level"] == "cell", c].nunique() > 1 or c in ("machine", "scenario")
    ]
    return ", ".join(shown) if shown else "all cells"


def _cell_name(comparison: Comparison, row: object) -> str:
    parts = [str(getattr(row, c)) for c in comparison.cells if c not in comparison.groups]
    return " ".join(p.upper() if p.islower() and len(p) <= 4 else p for p in parts)


def _cells_sentence(comparison: Comparison, cells: pd.DataFrame) -> str:
    pieces = []
    for label in ("equivalent", "worse", "better", "inconclusive"):
        chosen = cells[cells["label"] == label]
        if chosen.empty:
            continue
        if label != "inconclusive":
            items = [f"{_cell_name(comparison, r)} ({fmt_delta(r)})" for r in chosen.itertuples()]
            pieces.append(f"{label} with {', '.join(items)}")
            continue
        by_reason: dict[str, list[str]] = {}
        for r in chosen.itertuples():
            item = f"{_cell_name(comparison, r)} ({fmt_delta(r)})"
            by_reason.setdefault(_short(r.reason), []).append(item)
        pieces += [f"inconclusive ({why}) with {', '.join(i)}" for why, i in by_reason.items()]
    return "; ".join(pieces)


def _over(comparison: Comparison, n_cells: int) -> str:
    """'5 classifiers' when the cells of a group differ by classifier only, else 'N cells'."""
    inner = [c for c in comparison.cells if c not in comparison.groups]
    return f"{n_cells} {inner[0]}s" if len(inner) == 1 else f"{n_cells} cells"


def _group_finding(comparison: Comparison, key: tuple, part: pd.DataFrame) -> Finding:
    base = comparison.baseline
    means = comparison.means
    sentences = []
    if key in means.index or (len(key) == 1 and key[0] in means.index):
        row = means.loc[key if len(key) > 1 else key[0]].sort_values(ascending=False)
        others = ", ".join(f"{name} {value:.3f}" for name, value in row.iloc[1:].items())
        sentences.append(
            f"Best {comparison.treatment}: {row.index[0]} (mean Macro F1 {row.iloc[0]:.3f} over "
            f"{_over(comparison, int(part['n_cells'].iloc[0]))}{'; ' + others if others else ''})."
        )
    cells = comparison.table[comparison.table["level"] == "cell"]
    for row in part.itertuples():
        mask = pd.Series(True, index=cells.index)
        for c, v in zip(comparison.groups, key, strict=True):
            mask &= cells[c] == v
        mine = cells[mask & (cells["candidate"] == row.candidate)]
        over = _over(comparison, int(row.n_cells))
        sentences.append(
            f"{row.candidate} vs {base}: {row.label} over the {over} ({fmt_delta(row)}); "
            f"{_cells_sentence(comparison, mine)}."
        )
    return Finding(_scope(comparison, key), " ".join(sentences))


def _overall_finding(comparison: Comparison, row: object) -> Finding:
    cells = comparison.table[
        (comparison.table["level"] == "cell") & (comparison.table["candidate"] == row.candidate)
    ]
    counts = cells["label"].value_counts()
    tally = ", ".join(f"{int(counts[k])} {k}" for k in counts.index)
    return Finding(
        f"overall, {row.candidate}",
        f"{row.candidate} vs {comparison.baseline} over {int(row.n_cells)} cells: {row.label} "
        f"({fmt_delta(row)}; mean Macro F1 {row.candidate_mean:.3f} vs "
        f"{row.baseline_mean:.3f}); cells: {tally}.",
    )


def _ranking_finding(comparison: Comparison) -> Finding:
    ranking = comparison.ranking
    name = comparison.treatment
    if ranking is None:
        return Finding("ranking", f"Friedman/Nemenyi {comparison.ranking_note}.")
    ranks = ", ".join(f"{n} {r:.2f}" for n, r in ranking.ranks.items())
    pairs = ranking.groups()
    if pairs:
        apart = "; ".join(f"{a} ranks above {b}" for a, b in pairs)
        post = f"significantly different (Nemenyi p < {ranking.alpha:g}): {apart}"
    else:
        post = "no two of them differ by more than the CD"
    cells = comparison.table[comparison.table["level"] == "cell"]
    varying = [c for c in comparison.cells if cells[c].nunique() > 1] or comparison.cells
    text = (
        f"Friedman test over {ranking.n_blocks} blocks ({' × '.join(varying)}), "
        f"{ranking.k} {name}s: χ²_F = {ranking.chi2:.2f}, p = {ranking.p_value:.3g} "
        f"(Iman–Davenport F_F = {ranking.ff:.2f}, p = {ranking.p_ff:.3g}). Average ranks "
        f"(1 = best): {ranks}; Nemenyi CD = {ranking.cd:.2f} at α = {ranking.alpha:g}; {post}."
    )
    return Finding("ranking", text)


def _caveats(comparison: Comparison) -> list[Finding]:
    table = comparison.table
    if "test_runs_per_class" not in table:
        return []
    single = table[(table["level"] == "cell") & (table["test_runs_per_class"] == 1)]
    if single.empty:
        return []
    where = []
    for cell in sorted({(str(r.machine), str(r.scenario)) for r in single.itertuples()}):
        names, count = comparison.single_run_classes.get(cell, ([], 0))
        which = "every class" if names and len(names) == count else ", ".join(names)
        where.append(" ".join(cell) + (f" ({which})" if which else ""))
    return [
        Finding(
            "caveat",
            f"classes with a single physical test run: {', '.join(where)}: the recording CI "
            "there resamples that run's channels (simultaneous views of one event), not runs, so "
            "it understates run-to-run variation.",
        )
    ]


def verdict(comparison: Comparison) -> list[Finding]:
    """The verdict as findings: per group, per candidate overall, ranking, caveats."""
    table = comparison.table
    findings = []
    groups = table[table["level"] == "group"]
    if comparison.groups and not groups.empty:
        for key, part in groups.groupby(comparison.groups, sort=False):
            key = key if isinstance(key, tuple) else (key,)
            findings.append(_group_finding(comparison, key, part))
    for row in table[table["level"] == "overall"].itertuples():
        findings.append(_overall_finding(comparison, row))
    findings.append(_ranking_finding(comparison))
    return findings + _caveats(comparison)
