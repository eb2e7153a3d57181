"""Known truth on hand-made results: identical, clearly worse, and undecidable sensors."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.verdict import compare, interval_label, stack_folders, verdict

MACHINES, SCENARIOS, CLASSIFIERS = (
    ("M2", "M4"),
    ("forward", "backward", "interpolation"),
    (
        "lr",
        "knn",
        "rf",
    ),
)


def _results(candidates: dict[str, tuple[float, float]], repeats: int = 10, seed: int = 0):
    """Reference plus sensors whose Macro F1 = reference + shift + N(0, sd), per run."""
    rng = np.random.default_rng(seed)
    rows = []
    for machine in MACHINES:
        for scenario in SCENARIOS:
            for clf in CLASSIFIERS:
                level = rng.uniform(0.4, 0.8)
                for repeat in range(repeats):
                    ref = level + rng.normal(0, 0.01)
                    values = {"ref": ref}
                    for name, (shift, sd) in candidates.items():
                        values[name] = ref + shift + (rng.normal(0, sd) if sd else 0.0)
                    for sensor, f1 in values.items():
                        rows.append(
                            dict(
                                dataset="d",
                                feature_set="paper8",
                                machine=machine,
                                scenario=scenario,
                                sensor=sensor,
                                classifier=clf,
                                repeat=repeat,
                                macro_f1=f1,
                                status="ok",
                            )
                        )
    return pd.DataFrame(rows)


@pytest.fixture(scope="module")
def known():
    results = _results({"same": (0.0, 0.0), "shifted": (-0.1, 0.002), "noisy": (-0.01, 0.08)})
    return compare(results, "ref", margin=0.02)


def _labels(comparison, candidate, level="cell"):
    table = comparison.table
    return table[(table["level"] == level) & (table["candidate"] == candidate)]["label"]


def test_identical_sensors_are_equivalent_everywhere(known):
    for level, count in (("cell", 18), ("group", 6), ("overall", 1)):
        labels = _labels(known, "same", level)
        assert len(labels) == count and set(labels) == {"equivalent"}
    same = known.table[known.table["candidate"] == "same"]
    assert np.all(same["delta"] == 0) and np.all(same["p_value"] == 1)


def test_a_shift_of_0_1_with_small_noise_is_worse_in_every_cell(known):
    for level in ("cell", "group", "overall"):
        assert set(_labels(known, "shifted", level)) == {"worse"}
    cells = known.table[(known.table["level"] == "cell") & (known.table["candidate"] == "shifted")]
    assert cells["delta"].to_numpy() == pytest.approx(-0.1, abs=0.003)
    assert np.all(cells["p_holm"] < 0.05)


def test_a_shift_of_0_01_with_large_noise_is_inconclusive(known):
    labels = _labels(known, "noisy")
    assert set(labels) == {"inconclusive"}
    cells = known.table[(known.table["level"] == "cell") & (known.table["candidate"] == "noisy")]
    assert all(r.startswith("too few repetitions") for r in cells["reason"])
    assert np.all(cells["ci_low"] < -0.02) and np.all(cells["ci_high"] > -0.02)


def test_group_rows_average_the_cells_per_repetition(known):
    table = known.table
    cells = table[(table["level"] == "cell") & (table["candidate"] == "noisy")]
    group = table[(table["level"] == "group") & (table["candidate"] == "noisy")]
    first = group.iloc[0]
    mine = cells[(cells["machine"] == first["machine"]) & (cells["scenario"] == first["scenario"])]
    assert len(mine) == 3 and first["n_cells"] == 3
    # with every repetition present in every cell, the mean of per-repetition means is the
    # mean of the cell means
    assert first["delta"] == pytest.approx(mine["delta"].mean())


def test_deterministic_pairs_sd_zero_are_decided_by_the_margin():
    results = _results({"close": (0.005, 0.0), "far": (-0.05, 0.0)})
    # the reference's own noise cancels in the paired difference: SD exactly 0 or rounding
    comparison = compare(results, "ref")
    assert set(_labels(comparison, "close")) == {"equivalent"}
    assert set(_labels(comparison, "far")) == {"worse"}


def test_one_repetition_is_inconclusive_with_the_reason():
    comparison = compare(_results({"a": (-0.1, 0.0)}, repeats=1), "ref")
    cells = comparison.table[comparison.table["level"] == "cell"]
    assert set(cells["label"]) == {"inconclusive"}
    assert all("too few repetitions (1)" in r for r in cells["reason"])


def test_friedman_ranks_the_shifted_sensor_last(known):
    ranking = known.ranking
    assert ranking is not None and ranking.n_blocks == 18
    assert ranking.ranks.index[-1] == "shifted" and ranking.ranks["shifted"] == 4.0
    assert ("ref", "shifted") in ranking.groups() or ("same", "shifted") in ranking.groups()


def test_sentences_cite_the_numbers_of_the_table(known):
    findings = verdict(known)
    overall = next(f for f in findings if f.scope == "overall, shifted")
    row = known.table[(known.table["level"] == "overall") & (known.table["candidate"] == "shifted")]
    row = row.iloc[0]
    assert f"Δ {row['delta']:+.3f} [{row['ci_low']:+.3f}, {row['ci_high']:+.3f}]" in overall.text
    assert "worse" in overall.text and "18 worse" in overall.text
    group = next(f for f in findings if f.scope == "M2, forward")
    assert "Best sensor: " in group.text and "same vs ref: equivalent" in group.text
    ranking = next(f for f in findings if f.scope == "ranking")
    assert f"CD = {known.ranking.cd:.2f}" in ranking.text


def test_interval_labels_at_the_margins():
    assert interval_label(-0.019, 0.019, 0.02) == "equivalent"
    assert interval_label(-0.021, 0.0, 0.02) == "inconclusive"
    assert interval_label(-0.3, -0.021, 0.02) == "worse"
    assert interval_label(0.021, 0.3, 0.02) == "better"
    assert interval_label(-0.3, 0.3, 0.02) == "inconclusive"
    assert interval_label(np.nan, np.nan, 0.02) is None


def test_two_tables_compare_as_sources():
    a = _results({}, seed=1)
    b = a.assign(macro_f1=a["macro_f1"] - 0.1)
    both = stack_folders([a, b], ["paper8", "mine"])
    comparison = compare(
        both,
        "paper8",
        treatment="source",
        cells=["machine", "scenario", "sensor", "classifier"],
    )
    cells = comparison.table[comparison.table["level"] == "cell"]
    assert len(cells) == 18 and set(cells["label"]) == {"worse"}
    assert cells["delta"].to_numpy() == pytest.approx(-0.1)
    assert comparison.ranking is None and "3 sources" in comparison.ranking_note


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"baseline": "ref", "margin": 0.0}, "margin must be"),
        ({"baseline": "ref", "margin": -0.02}, "margin must be"),
        ({"baseline": "adxl999"}, "baseline 'adxl999' has no successful run"),
    ],
)
def test_bad_input_is_one_clear_error(kwargs, message):
    with pytest.raises(SDTError, match=message):
        compare(_results({"a": (0.0, 0.01)}, repeats=2), **kwargs)


def test_nothing_to_pair_is_an_error():
    results = _results({"a": (0.0, 0.01)}, repeats=2)
    mine = results["sensor"] == "a"
    results.loc[mine, "machine"] = results.loc[mine, "machine"] + "-elsewhere"
    with pytest.raises(SDTError, match="nothing to pair"):
        compare(results, "ref")
    with pytest.raises(SDTError, match="nothing to compare"):
        compare(results[results["sensor"] == "ref"], "ref")
