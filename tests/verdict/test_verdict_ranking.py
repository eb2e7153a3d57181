"""Friedman, Iman-Davenport, Nemenyi and the critical difference against Demšar (2006).

Source: J. Demšar, "Statistical Comparisons of Classifiers over Multiple Data
Sets", JMLR 7 (2006) 1-30, section 3.2.2: Table 5(a) (Nemenyi critical values)
and Table 6 (AUC of C4.5, C4.5+m, C4.5+cf, C4.5+m+cf on 14 data sets), with the
worked values average ranks 3.143 / 2.000 / 2.893 / 1.964, chi2_F = 9.28,
F_F = 3.69, CD = 2.569 sqrt(4*5 / (6*14)) = 1.25 (alpha 0.05) and 1.12 (alpha 0.10).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from sdt_framework.verdict import critical_difference, friedman_nemenyi, plot_cd_diagram, q_alpha

NAMES = ["C4.5", "C4.5+m", "C4.5+cf", "C4.5+m+cf"]
# Table 6 as printed. In the "voting" row C4.5+cf and C4.5+m+cf both print 0.975 yet the
# paper ranks them 2 and 3 (the unrounded AUCs differed), so C4.5+cf gets 0.9751 here to
# reproduce the published ranks; every other value is as printed.
TABLE6 = [
    [0.763, 0.768, 0.771, 0.798],  # adult (sample)
    [0.599, 0.591, 0.590, 0.569],  # breast cancer
    [0.954, 0.971, 0.968, 0.967],  # breast cancer wisconsin
    [0.628, 0.661, 0.654, 0.657],  # cmc
    [0.882, 0.888, 0.886, 0.898],  # ionosphere
    [0.936, 0.931, 0.916, 0.931],  # iris
    [0.661, 0.668, 0.609, 0.685],  # liver disorders
    [0.583, 0.583, 0.563, 0.625],  # lung cancer
    [0.775, 0.838, 0.866, 0.875],  # lymphography
    [1.000, 1.000, 1.000, 1.000],  # mushroom
    [0.940, 0.962, 0.965, 0.962],  # primary tumor
    [0.619, 0.666, 0.614, 0.669],  # rheum
    [0.972, 0.981, 0.9751, 0.975],  # voting
    [0.957, 0.978, 0.946, 0.970],  # wine
]
PUBLISHED_RANKS = {"C4.5": 3.143, "C4.5+m": 2.000, "C4.5+cf": 2.893, "C4.5+m+cf": 1.964}
#: Table 5(a), q_0.05 for k = 2..10 classifiers
Q05 = [1.960, 2.343, 2.569, 2.728, 2.850, 2.949, 3.031, 3.102, 3.164]
TABLE5A = dict(zip(range(2, 11), Q05, strict=True))


@pytest.fixture(scope="module")
def scores() -> pd.DataFrame:
    return pd.DataFrame(TABLE6, columns=NAMES)


def test_nemenyi_critical_values_match_table_5a():
    for k, published in TABLE5A.items():
        assert q_alpha(k) == pytest.approx(published, abs=0.0015), k  # table rounds to 3 places


def test_average_ranks_friedman_and_iman_davenport_match_the_paper(scores):
    ranking = friedman_nemenyi(scores)
    for name, published in PUBLISHED_RANKS.items():
        assert ranking.ranks[name] == pytest.approx(published, abs=5e-4)
    assert list(ranking.ranks.index) == ["C4.5+m+cf", "C4.5+m", "C4.5+cf", "C4.5"]
    # the paper's formulas, computed here from its published average ranks
    n, k = 14, 4
    r = np.array(list(PUBLISHED_RANKS.values()))
    chi2 = 12 * n / (k * (k + 1)) * (np.sum(r**2) - k * (k + 1) ** 2 / 4)
    ff = (n - 1) * chi2 / (n * (k - 1) - chi2)
    assert round(chi2, 2) == 9.28 and round(ff, 2) == 3.69  # the published values
    assert ranking.chi2_uncorrected == pytest.approx(chi2, abs=0.01)
    assert ranking.ff == pytest.approx(ff, abs=0.01)
    assert ranking.n_blocks == 14


def test_scipy_friedman_is_the_tie_corrected_statistic(scores):
    ranking = friedman_nemenyi(scores)
    # ties: iris (2), lung cancer (2), mushroom (4), primary tumor (2): sum(t^3 - t) = 78
    correction = 1 - 78 / (14 * 4 * (4**2 - 1))
    assert ranking.chi2 == pytest.approx(ranking.chi2_uncorrected / correction)


def test_critical_difference_and_nemenyi_conclusions_match_the_paper(scores):
    assert round(critical_difference(4, 14, 0.05), 2) == 1.25
    assert round(critical_difference(4, 14, 0.10), 2) == 1.12
    ranking = friedman_nemenyi(scores)
    assert ranking.cd == pytest.approx(2.569 * np.sqrt(4 * 5 / (6 * 14)), abs=1e-3)
    # "the post-hoc test is not powerful enough to detect any significant differences"
    assert ranking.groups() == []
    # at p = 0.10: "pure C4.5 is significantly worse than C4.5+m and C4.5+m+cf", C4.5+cf open
    p = ranking.nemenyi
    assert p.loc["C4.5", "C4.5+m"] < 0.10 and p.loc["C4.5", "C4.5+m+cf"] < 0.10
    assert p.loc["C4.5", "C4.5+cf"] > 0.10 and p.loc["C4.5+cf", "C4.5+m+cf"] > 0.10
    ranks = ranking.ranks
    for a in NAMES:
        for b in NAMES:
            if a != b:  # Nemenyi p < 0.10 exactly when the ranks differ by more than the CD
                apart = abs(ranks[a] - ranks[b]) > critical_difference(4, 14, 0.10)
                assert (p.loc[a, b] < 0.10) == apart


def test_fewer_than_three_treatments_is_refused(scores):
    with pytest.raises(ValueError, match="3 treatments"):
        friedman_nemenyi(scores[NAMES[:2]])


def test_cd_diagram_is_drawn(scores, tmp_path):
    from matplotlib import image

    fig = plot_cd_diagram(friedman_nemenyi(scores), title="Demšar 2006, Table 6")
    path = tmp_path / "cd.png"
    fig.savefig(path, dpi=110)
    pixels = image.imread(path)
    assert pixels.shape[1] > 600 and pixels.shape[0] > 200
    dark = (pixels[..., :3].mean(axis=2) < 0.5).mean()
    assert 0.005 < dark < 0.3  # lines and labels, not an empty canvas


def test_cd_diagram_keeps_long_sweep_point_labels_inside_the_figure():
    """Design-point names share their base: it is dropped from the labels, which all fit."""
    rng = np.random.default_rng(3)
    base = "adxl345-ds[errors=datasheet,odr=3200,range=16g,temp=85c]"
    names = ["wilcoxon-786b10", base] + [
        f"{base}~nonlinearity.second_pct_fs={v},gauss-markov.sigma_ug={w}"
        for v in (0, 0.5, 32)
        for w in (0, 1e4)
    ]
    table = pd.DataFrame(rng.uniform(0.3, 0.6, (12, len(names))), columns=names)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = plot_cd_diagram(friedman_nemenyi(table))
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    renderer = canvas.get_renderer()
    box = fig.bbox
    labels = [t for ax in fig.axes for t in ax.texts if "(" in t.get_text()]
    assert len(labels) == len(names)
    for text in labels:
        extent = text.get_window_extent(renderer)
        assert extent.x0 >= box.x0 and extent.x1 <= box.x1, text.get_text()
    shown = " ".join(t.get_text() for t in labels)
    assert "~nonlinearity.second_pct_fs=0.5" in shown and f"{base}~" not in shown
    assert f"of {base}" in fig.texts[0].get_text()  # the base is named once, in the title
