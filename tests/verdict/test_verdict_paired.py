"""Paired t interval, p-values, TOST and Holm against scipy's own tests and a worked example."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from sdt_framework.verdict.paired import holm, paired_t_pvalue, t_interval, tost_pvalue


def _summary(d: np.ndarray) -> tuple[float, float, int]:
    return float(d.mean()), float(d.std(ddof=1)), len(d)


@pytest.mark.parametrize("n", [2, 3, 10])
def test_t_interval_and_p_value_match_scipy(n):
    d = np.random.default_rng(n).normal(-0.03, 0.02, n)
    mean, sd, count = _summary(d)
    low, high = t_interval(mean, sd, count, 0.95)
    expected = stats.t.interval(0.95, n - 1, loc=mean, scale=stats.sem(d))
    assert (low, high) == pytest.approx(expected, rel=1e-12)
    assert paired_t_pvalue(mean, sd, count) == pytest.approx(stats.ttest_1samp(d, 0).pvalue)


@pytest.mark.parametrize("shift", [-0.05, -0.01, 0.0, 0.015, 0.04])
def test_tost_is_the_larger_of_two_one_sided_scipy_tests(shift):
    d = np.random.default_rng(7).normal(shift, 0.01, 10)
    margin = 0.02
    lower = stats.ttest_1samp(d, -margin, alternative="greater").pvalue
    upper = stats.ttest_1samp(d, margin, alternative="less").pvalue
    assert tost_pvalue(*_summary(d), margin) == pytest.approx(max(lower, upper))


def test_tost_at_half_alpha_agrees_with_the_interval_inside_the_margins():
    rng = np.random.default_rng(3)
    for _ in range(200):
        d = rng.normal(rng.uniform(-0.04, 0.04), rng.uniform(0.001, 0.03), 5)
        low, high = t_interval(*_summary(d), 0.95)
        inside = low > -0.02 and high < 0.02
        assert (tost_pvalue(*_summary(d), 0.02) < 0.025) == inside


def test_zero_spread_is_exactly_known():
    # a deterministic pair (reference with lr/knn/xgb): constant differences
    low, high = t_interval(-0.05, 0.0, 10)
    assert low == high == -0.05
    assert paired_t_pvalue(-0.05, 0.0, 10) == 0.0
    assert paired_t_pvalue(0.0, 0.0, 10) == 1.0
    assert tost_pvalue(0.01, 0.0, 10, 0.02) == 0.0
    assert tost_pvalue(-0.05, 0.0, 10, 0.02) == 1.0


def test_a_single_repetition_gives_no_interval_and_no_p_value():
    low, high = t_interval(0.1, np.nan, 1)
    assert np.isnan(low) and np.isnan(high)
    assert np.isnan(paired_t_pvalue(0.1, np.nan, 1))
    assert np.isnan(tost_pvalue(0.1, np.nan, 1, 0.02))


def test_holm_on_demsar_2006_worked_example():
    # Demšar (2006), section 3.2.2: p = 0.016, 0.019, 0.607 against alpha/i = 0.017, 0.025,
    # 0.050; "The Holm procedure rejects the first and then the second hypothesis".
    adjusted = holm(np.array([0.607, 0.016, 0.019]))
    # by hand: 3 * 0.016 = 0.048; max(0.048, 2 * 0.019 = 0.038) = 0.048; max(0.048, 0.607)
    assert adjusted == pytest.approx([0.607, 0.048, 0.048])
    assert list(adjusted < 0.05) == [False, True, True]


def test_holm_matches_statsmodels_and_skips_nan():
    multitest = pytest.importorskip("statsmodels.stats.multitest")  # comes with scikit-posthocs
    p = np.random.default_rng(0).uniform(0, 0.2, 30)
    expected = multitest.multipletests(p, method="holm")[1]
    assert holm(p) == pytest.approx(expected)
    with_nan = np.concatenate([p[:3], [np.nan]])
    out = holm(with_nan)
    assert np.isnan(out[3])
    assert out[:3] == pytest.approx(multitest.multipletests(p[:3], method="holm")[1])
