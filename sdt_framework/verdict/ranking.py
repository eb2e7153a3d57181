"""Ranking many sensors over many cells: Friedman test, Nemenyi post-hoc, critical difference.

Demšar (2006, JMLR 7:1-30, section 3.2.2): rank the k treatments within each
of N blocks (rank 1 = best, ties share the average rank), compare the average
ranks R_j. The Friedman statistic

    chi2_F = 12 N / (k (k+1)) * (sum_j R_j^2 - k (k+1)^2 / 4)

is chi-squared with k-1 degrees of freedom under "all equal"; Iman and
Davenport's F_F = (N-1) chi2_F / (N (k-1) - chi2_F) follows F(k-1, (k-1)(N-1))
and is less conservative. Two treatments differ (Nemenyi) when their average
ranks differ by at least CD = q_alpha sqrt(k (k+1) / (6 N)), q_alpha being the
studentized range quantile (infinite degrees of freedom) divided by sqrt(2).

The p-value reported with the Friedman test is scipy's, which corrects
chi2_F for ties; ``chi2_uncorrected`` and ``ff`` follow the paper's formulas
above (they agree when there are no ties).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy import stats

__all__ = ["DegenerateBlocksError", "Ranking", "critical_difference", "friedman_nemenyi", "q_alpha"]


class DegenerateBlocksError(ValueError):
    """Blocks the Friedman statistic is not defined on: every block ties every treatment."""


def q_alpha(k: int, alpha: float = 0.05) -> float:
    """Nemenyi critical value for k treatments (Demšar 2006, Table 5(a))."""
    return float(stats.studentized_range.ppf(1 - alpha, k, np.inf) / np.sqrt(2))


def critical_difference(k: int, n: int, alpha: float = 0.05) -> float:
    """CD = q_alpha sqrt(k (k+1) / (6 N)) for k treatments over N blocks."""
    return q_alpha(k, alpha) * float(np.sqrt(k * (k + 1) / (6 * n)))


@dataclass(frozen=True)
class Ranking:
    """Friedman/Nemenyi result over N blocks and k treatments."""

    ranks: pd.Series  # average rank per treatment, 1 = best, ascending
    n_blocks: int
    chi2: float  # scipy.stats.friedmanchisquare (tie-corrected)
    p_value: float
    chi2_uncorrected: float  # Demšar's formula from the average ranks
    ff: float  # Iman-Davenport F_F from chi2_uncorrected
    p_ff: float
    cd: float
    alpha: float
    nemenyi: pd.DataFrame  # pairwise p-values (scikit-posthocs)

    @property
    def k(self) -> int:
        """Number of treatments."""
        return len(self.ranks)

    def groups(self) -> list[tuple[str, str]]:
        """Pairs (better, worse) whose Nemenyi p-value is below alpha, best pairs first."""
        names = list(self.ranks.index)
        return [
            (a, b)
            for i, a in enumerate(names)
            for b in names[i + 1 :]
            if self.nemenyi.loc[a, b] < self.alpha
        ]


def friedman_nemenyi(scores: pd.DataFrame, alpha: float = 0.05) -> Ranking:
    """Friedman test and Nemenyi post-hoc on a blocks x treatments table of scores.

    Parameters
    ----------
    scores
        One row per block (e.g. machine x scenario x classifier), one column per
        treatment (sensor); higher is better. Rows with a missing value are dropped.
    alpha
        Significance level of the critical difference.

    Raises
    ------
    ValueError
        Fewer than 3 treatments or 2 complete blocks (the test is not defined).
    DegenerateBlocksError
        Every block gives all treatments the same score: the tie-corrected
        statistic is 0/0 (scipy would warn and return NaN), nothing ranks.
    """
    import scikit_posthocs as sp

    scores = scores.dropna()
    n, k = scores.shape
    if k < 3 or n < 2:
        raise ValueError(f"Friedman needs >= 3 treatments and >= 2 blocks, got {k} and {n}")
    values = scores.to_numpy(float)
    if np.all(values == values[:, :1]):
        raise DegenerateBlocksError(
            f"every one of the {n} blocks gives all {k} treatments the same Macro F1 "
            f"(e.g. {values[0, 0]:.3f}), so there is nothing to rank"
        )
    ranks = stats.rankdata(-values, axis=1)
    average = pd.Series(ranks.mean(axis=0), index=scores.columns).sort_values(kind="stable")
    test = stats.friedmanchisquare(*scores.to_numpy(float).T)
    chi2 = 12 * n / (k * (k + 1)) * (float(np.sum(average**2)) - k * (k + 1) ** 2 / 4)
    spare = n * (k - 1) - chi2  # 0 when every block ranks the treatments alike
    ff = (n - 1) * chi2 / spare if spare > 1e-12 else np.inf
    p_ff = float(stats.f.sf(ff, k - 1, (k - 1) * (n - 1))) if np.isfinite(ff) else 0.0
    nemenyi = sp.posthoc_nemenyi_friedman(scores.to_numpy(float))
    nemenyi.index = nemenyi.columns = scores.columns
    return Ranking(
        average,
        n,
        float(test.statistic),
        float(test.pvalue),
        float(chi2),
        float(ff),
        p_ff,
        critical_difference(k, n, alpha),
        alpha,
        nemenyi.loc[average.index, average.index],
    )
