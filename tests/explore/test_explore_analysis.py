"""Analysis functions on hand-made exploration tables with a known answer."""

from __future__ import annotations

import itertools

import numpy as np
import pandas as pd
import pytest

from sdt_framework.explore import (
    design_points,
    main_effects,
    min_spec,
    pareto_front,
    parse_sweep,
    sensitivity,
    with_best,
)
from sdt_framework.explore.minspec import meeting_points
from sdt_framework.explore.sweep import DEMAND, Target


def fake_results(design: pd.DataFrame, f1, repeats: int = 5, noise: float = 0.0) -> pd.DataFrame:
    """Tidy table where Macro-F1 = f1(row) + Gaussian noise, for one cell."""
    gen = np.random.default_rng(1)
    rows = []
    fields = [c for c in design.columns if c != "design_index" and not c.startswith("u_")]
    for _, point in design.iterrows():
        for r in range(repeats):
            rows.append(
                {
                    "point": f"p{int(point['design_index'])}",
                    "role": "point",
                    "machine": "m",
                    "scenario": "forward",
                    "classifier": "lr",
                    "repeat": r,
                    "macro_f1": f1(point) + noise * gen.standard_normal(),
                    **point.to_dict(),
                }
            )
    frame = pd.DataFrame(rows)
    frame["design_index"] = frame["design_index"].astype(int)
    return frame, fields


GRID = {
    "base": "adxl345",
    "axes": {
        "sampling_rate_hz": {"levels": [800, 1600, 3200, 6400]},
        "noise_density_ug_rthz": {"levels": [25, 90, 290, 1000]},
        "adc_bits": {"levels": [10, 13, 16]},
    },
}


def test_anova_ranks_the_only_active_parameter_first_and_the_others_near_zero():
    sweep = parse_sweep(GRID)
    design = design_points(sweep)
    results, _ = fake_results(
        design, lambda p: 0.5 + 0.1 * np.log2(p["sampling_rate_hz"] / 800), noise=0.01
    )
    table = sensitivity(results, sweep, len(design))
    shares = table.set_index("term")["value"]
    assert shares["sampling_rate_hz"] > 0.99
    for term in ["noise_density_ug_rthz", "adc_bits", "sampling_rate_hz:adc_bits"]:
        assert shares[term] < 0.005
    assert table.set_index("term").loc["sampling_rate_hz", "rank"] == 1
    low, high = table.set_index("term").loc["sampling_rate_hz", ["ci_low", "ci_high"]]
    assert low <= shares["sampling_rate_hz"] <= high


def test_anova_shares_of_an_additive_model_match_the_analytic_variance_split():
    # y = a_i + b_j on a 2 x 2 grid with a = (0, 2), b = (0, 1): Var(a) = 1, Var(b) = 1/4
    sweep = parse_sweep(
        {
            "base": "adxl345",
            "axes": {"adc_bits": {"levels": [10, 12]}, "digital_order": {"levels": [1, 2]}},
        }
    )
    design = design_points(sweep)
    results, _ = fake_results(
        design, lambda p: 2.0 * (p["adc_bits"] == 12) + 1.0 * (p["digital_order"] == 2)
    )
    shares = sensitivity(results, sweep, len(design)).set_index("term")["value"]
    assert shares["adc_bits"] == pytest.approx(1 / 1.25)
    assert shares["digital_order"] == pytest.approx(0.25 / 1.25)
    assert abs(shares["adc_bits:digital_order"]) < 1e-12


@pytest.mark.parametrize("design", ["morris", "sobol", "lhs"])
def test_salib_designs_rank_the_only_active_parameter_first(design):
    sweep = parse_sweep(
        {
            "base": "adxl345",
            "design": design,
            "samples": 64 if design != "morris" else 20,
            "axes": {
                "sampling_rate_hz": {"range": [800, 6400], "scale": "log"},
                "noise_density_ug_rthz": {"range": [25, 1000], "scale": "log"},
                "full_scale_g": {"range": [2, 16]},
            },
        }
    )
    points = design_points(sweep)
    results, _ = fake_results(points, lambda p: 0.4 + 0.3 * p["u_noise_density_ug_rthz"], repeats=2)
    table = sensitivity(results, sweep, len(points))
    first = {"morris": "mu_star", "sobol": "ST", "lhs": "delta"}[design]
    ranked = table[table["index"] == first].sort_values("value", ascending=False)
    assert ranked.iloc[0]["term"] == "noise_density_ug_rthz"
    if design != "lhs":  # delta has a positive bias floor on finite samples
        others = ranked.iloc[1:]["value"].abs()
        assert (others < 0.05 * ranked.iloc[0]["value"]).all()


def test_min_spec_returns_the_analytic_threshold_of_a_monotone_curve():
    levels = list(np.geomspace(10, 2000, 25))
    sweep = parse_sweep(
        {
            "base": "adxl345",
            "axes": {"noise_density_ug_rthz": {"levels": levels}, "adc_bits": {"levels": [13, 16]}},
        }
    )
    design = design_points(sweep)
    # F1 falls linearly with noise density: 1 - nsd / 2000 >= 0.8  <=>  nsd <= 400
    results, fields = fake_results(design, lambda p: 1.0 - p["noise_density_ug_rthz"] / 2000)
    table = min_spec(
        results,
        fields,
        {"noise_density_ug_rthz": levels[10], "adc_bits": 13},
        Target(macro_f1=0.8),
        DEMAND,
    )
    row = table.set_index("parameter").loc["noise_density_ug_rthz"]
    assert row["min_level"] == pytest.approx(max(v for v in levels if v <= 400))
    # bits do not matter: the least demanding tested level (13) already meets the target
    assert table.set_index("parameter").loc["adc_bits", "min_level"] == 13


def test_min_spec_needs_every_more_demanding_level_to_meet():
    sweep = parse_sweep(
        {"base": "adxl345", "axes": {"sampling_rate_hz": {"levels": [800, 1600, 3200, 6400]}}}
    )
    design = design_points(sweep)
    scores = {800: 0.9, 1600: 0.5, 3200: 0.85, 6400: 0.95}  # 800 is a lucky outlier
    results, fields = fake_results(design, lambda p: scores[p["sampling_rate_hz"]])
    table = min_spec(results, fields, {"sampling_rate_hz": 3200}, Target(macro_f1=0.8), DEMAND)
    assert table.iloc[0]["min_level"] == 3200
    met = meeting_points(results, fields, Target(macro_f1=0.8))
    assert sorted(met["sampling_rate_hz"]) == [800, 3200, 6400]


def test_targets_relative_to_the_reference():
    sweep = parse_sweep(
        {"base": "adxl345", "axes": {"sampling_rate_hz": {"levels": [800, 1600, 3200]}}}
    )
    design = design_points(sweep)
    results, fields = fake_results(design, lambda p: p["sampling_rate_hz"] / 4000)
    reference = results.iloc[:3].assign(point="ref", role="reference", macro_f1=1.0)
    both = pd.concat([results, reference], ignore_index=True)
    base = {"sampling_rate_hz": 3200}
    loss = min_spec(both, fields, base, Target(max_loss=0.5), DEMAND)  # needs >= 0.5
    share = min_spec(both, fields, base, Target(fraction_of_reference=0.3), DEMAND)  # >= 0.3
    assert loss.iloc[0]["min_level"] == 3200
    assert share.iloc[0]["min_level"] == 1600


def brute_force_front(cost, score):
    keep = []
    for i in range(len(cost)):
        dominated = any(
            cost[j] <= cost[i]
            and score[j] >= score[i]
            and (cost[j] < cost[i] or score[j] > score[i])
            for j in range(len(cost))
        )
        keep.append(not dominated)
    return np.array(keep)


def test_pareto_front_equals_a_brute_force_non_dominated_filter():
    gen = np.random.default_rng(7)
    cost = gen.integers(0, 10, 200).astype(float)  # many ties on purpose
    score = gen.integers(0, 10, 200) / 10
    assert (pareto_front(cost, score) == brute_force_front(cost, score)).all()
    hand = pareto_front(np.array([1.0, 2, 3, 3, 4]), np.array([0.5, 0.4, 0.9, 0.9, 0.8]))
    assert hand.tolist() == [True, False, True, True, False]


def test_main_effects_average_within_repetitions_and_give_t_intervals():
    sweep = parse_sweep(
        {
            "base": "adxl345",
            "axes": {"sampling_rate_hz": {"levels": [800, 1600]}, "adc_bits": {"levels": [10, 12]}},
        }
    )
    design = design_points(sweep)
    results, fields = fake_results(design, lambda p: p["sampling_rate_hz"] / 1600, noise=0.05)
    effects = main_effects(results, fields)
    row = effects[(effects["parameter"] == "sampling_rate_hz") & (effects["level"] == 800)].iloc[0]
    at = results[results["sampling_rate_hz"] == 800]
    per_repeat = at.groupby("repeat")["macro_f1"].mean().to_numpy()
    assert row["macro_f1"] == pytest.approx(per_repeat.mean())
    half = 2.7764451051977987 * per_repeat.std(ddof=1) / np.sqrt(5)  # t(0.975, 4)
    assert row["ci_high"] - row["macro_f1"] == pytest.approx(half)


def test_best_of_classifiers_picks_the_highest_mean_per_point():
    rows = []
    for clf, score in [("lr", 0.6), ("rf", 0.8)]:
        for r in range(3):
            rows.append(
                {
                    "point": "p",
                    "role": "point",
                    "machine": "m",
                    "scenario": "s",
                    "classifier": clf,
                    "repeat": r,
                    "macro_f1": score + 0.01 * r,
                }
            )
    out = with_best(pd.DataFrame(rows))
    best = out[out["classifier"] == "best"]
    assert best["macro_f1"].tolist() == pytest.approx([0.8, 0.81, 0.82])


def test_grid_design_is_the_full_factorial():
    design = design_points(parse_sweep(GRID))
    assert len(design) == 4 * 4 * 3
    combos = set(itertools.product([800, 1600, 3200, 6400], [25, 90, 290, 1000], [10, 13, 16]))
    got = {
        tuple(r)
        for r in design[["sampling_rate_hz", "noise_density_ug_rthz", "adc_bits"]]
        .to_numpy()
        .tolist()
    }
    assert got == combos
