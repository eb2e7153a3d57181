"""Paired statistics on differences between repetitions: t interval, paired t, TOST, Holm.

Every function works on summary arrays (mean, SD, count of the paired
differences of each comparison), so a whole comparison table is one
vectorised call. The paired t family is used rather than the Wilcoxon
signed-rank test: with the default 10 repetitions the exact Wilcoxon p-value
cannot go below 2/2**10 = 0.002, so after Holm's correction over 30 cells it
could never reject; the t-test uses the size of the differences, which are
themselves averages over hundreds of test windows.

A difference with SD 0 (a deterministic sensor-classifier pair, e.g. the
reference chain with lr, knn or xgb) is exactly known across repetitions: its
interval is the point itself, its p-value 0 when it is non-zero and 1 when it
is zero. Repetitions then add no evidence and the recording-level interval
(:mod:`.recordings`) is the only measure of uncertainty.
"""

from __future__ import annotations

import numpy as np
from scipy import stats

__all__ = ["holm", "paired_t_pvalue", "t_interval", "tost_pvalue"]


def _se(sd: np.ndarray, n: np.ndarray) -> np.ndarray:
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(n >= 2, sd / np.sqrt(n), np.nan)


def t_interval(
    mean: np.ndarray, sd: np.ndarray, n: np.ndarray, level: float = 0.95
) -> tuple[np.ndarray, np.ndarray]:
    """Two-sided Student-t interval of the mean paired difference.

    Parameters
    ----------
    mean, sd, n
        Mean, sample SD (ddof=1) and number of paired differences, per comparison.
    level
        Coverage, e.g. 0.95.

    Returns
    -------
    (low, high)
        NaN where fewer than two differences exist.
    """
    mean, sd, n = (np.asarray(a, dtype=float) for a in (mean, sd, n))
    with np.errstate(invalid="ignore"):
        q = stats.t.ppf(0.5 + level / 2, np.maximum(n - 1, 1))
    half = q * _se(sd, n)
    return mean - half, mean + half


def _t_tail(t: np.ndarray, df: np.ndarray) -> np.ndarray:
    """P(T >= t) with infinite t handled (SD 0)."""
    with np.errstate(invalid="ignore"):
        return stats.t.sf(t, np.maximum(df, 1))


def _statistic(shift: np.ndarray, sd: np.ndarray, n: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(shift / SE, degrees of freedom); SD 0 gives +-inf, or 0 when the shift is 0 too."""
    se = _se(sd, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        exact = np.where(shift == 0, 0.0, np.sign(shift) * np.inf)
        t = np.where(se > 0, shift / se, exact)
    return np.where(np.isnan(se), np.nan, t), n - 1


def paired_t_pvalue(mean: np.ndarray, sd: np.ndarray, n: np.ndarray) -> np.ndarray:
    """Two-sided p-value of the paired t-test of "mean difference = 0".

    Equals ``scipy.stats.ttest_1samp(d, 0).pvalue`` when SD > 0; SD 0 gives 0
    (non-zero difference) or 1 (zero difference); NaN below two differences.
    """
    mean, sd, n = (np.asarray(a, dtype=float) for a in (mean, sd, n))
    t, df = _statistic(mean, sd, n)
    p = 2 * _t_tail(np.abs(t), df)
    return np.where(np.isnan(t), np.nan, np.minimum(p, 1.0))


def tost_pvalue(mean: np.ndarray, sd: np.ndarray, n: np.ndarray, margin: float) -> np.ndarray:
    """Two one-sided tests of equivalence within (-margin, +margin).

    H0: |mean difference| >= margin. The p-value is the larger of the two
    one-sided t-test p-values (Schuirmann 1987); it is below alpha exactly
    when the two-sided (1 - 2 alpha) t interval lies inside the margins.
    """
    mean, sd, n = (np.asarray(a, dtype=float) for a in (mean, sd, n))
    t_low, df = _statistic(mean + margin, sd, n)  # H0: mean <= -margin
    t_high, _ = _statistic(mean - margin, sd, n)  # H0: mean >= +margin
    p = np.maximum(_t_tail(t_low, df), _t_tail(-t_high, df))
    return np.where(np.isnan(t_low), np.nan, p)


def holm(pvalues: np.ndarray) -> np.ndarray:
    """Holm's step-down adjusted p-values (Holm 1979); NaN entries stay NaN, uncounted.

    The i-th smallest of m p-values becomes max_{j<=i} min(1, (m - j + 1) p_(j)).
    """
    p = np.asarray(pvalues, dtype=float)
    out = np.full(p.shape, np.nan)
    valid = np.flatnonzero(~np.isnan(p))
    order = valid[np.argsort(p[valid], kind="stable")]
    m = len(order)
    scaled = (m - np.arange(m)) * p[order]
    out[order] = np.minimum(np.maximum.accumulate(scaled), 1.0)
    return out
