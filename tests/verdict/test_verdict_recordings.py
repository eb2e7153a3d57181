"""Resampling by recording: Macro F1 from counts, stratified draws, paired differences."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from sklearn.metrics import confusion_matrix, f1_score

from sdt_framework.bench.classify import recording_counts
from sdt_framework.verdict.recordings import RecordingSets, macro_f1, stratified_weights

CLASSES = ("healthy", "impeller", "bearing")


@pytest.mark.parametrize("seed", range(6))
def test_macro_f1_from_counts_matches_sklearn(seed):
    rng = np.random.default_rng(seed)
    y_true = rng.integers(0, 4, 60)
    y_pred = np.where(rng.random(60) < 0.6, y_true, rng.integers(0, 5, 60))
    if seed % 2:
        y_true[y_true == 2] = 0  # a class absent from the truth but maybe predicted
    matrix = confusion_matrix(y_true, y_pred, labels=range(5))
    expected = f1_score(y_true, y_pred, average="macro", zero_division=0)
    assert macro_f1(matrix) == pytest.approx(expected)


def test_stratified_weights_keep_each_class_size():
    strata = np.array([0, 0, 0, 1, 1, 2, 2, 2, 2])
    weights = stratified_weights(strata, 500, np.random.default_rng(0))
    for value, size in ((0, 3), (1, 2), (2, 4)):
        assert np.all(weights[:, strata == value].sum(axis=1) == size)
    # each item is drawn once per resample on average
    assert weights.mean(axis=0) == pytest.approx(np.ones(9), abs=0.15)


def _rows(label: str, repeat: int, truth: dict[str, int], pred: dict[str, int]) -> pd.DataFrame:
    """Per-recording counts of a run whose windows of recording r are all predicted pred[r]."""
    recordings = np.repeat(list(truth), 10)
    y_true = np.array([truth[r] for r in recordings])
    y_pred = np.array([pred[r] for r in recordings])
    entries = recording_counts(recordings, y_true, y_pred, CLASSES)
    frame = pd.DataFrame(entries, columns=["recording_id", "true", "predicted", "count"])
    return frame.assign(machine="M", scenario="forward", sensor=label, repeat=repeat)


TRUTH = {f"{c}-{k}": i for i, c in enumerate(CLASSES) for k in range(4)}  # 4 recordings a class


def test_recording_counts_sum_to_the_confusion_matrix():
    rng = np.random.default_rng(1)
    recordings = rng.choice(["a", "b", "c"], 90)
    y_true, y_pred = rng.integers(0, 3, 90), rng.integers(0, 3, 90)
    entries = recording_counts(recordings, y_true, y_pred, CLASSES)
    frame = pd.DataFrame(entries, columns=["recording_id", "true", "predicted", "count"])
    summed = frame.pivot_table("count", "true", "predicted", aggfunc="sum", fill_value=0)
    expected = confusion_matrix(y_true, y_pred, labels=range(3))
    assert summed.loc[list(CLASSES), list(CLASSES)].to_numpy().tolist() == expected.tolist()
    assert len(frame) == len(frame.drop_duplicates(["recording_id", "true", "predicted"]))


def _difference(candidate: pd.DataFrame, baseline: pd.DataFrame):
    both = pd.concat([candidate.assign(side="c"), baseline.assign(side="b")])
    sets = RecordingSets(both, ["machine", "scenario"], n_boot=4000, seed=0)
    coded = sets.frame
    sides = [coded[coded["side"] == side] for side in ("c", "b")]
    return sets.mean_difference(*sides, ("M", "forward"), [0])


def test_identical_sides_differ_by_exactly_zero_in_every_resample():
    side = _rows("a", 0, TRUTH, TRUTH)
    draws, reason = _difference(side, side.assign(sensor="b"))
    assert reason == "" and draws.shape == (4000,) and np.all(draws == 0)


def test_one_wrong_recording_gives_the_known_difference_and_a_spread():
    wrong = dict(TRUTH, **{"impeller-0": 2})  # one impeller recording called bearing
    candidate, baseline = _rows("a", 0, TRUTH, wrong), _rows("b", 0, TRUTH, TRUTH)
    draws, _ = _difference(baseline.assign(sensor="c"), candidate.assign(sensor="d"))
    # full sample, by sklearn: perfect (1.0) minus the Macro F1 with 10 of 120 windows wrong
    y_true = np.repeat([TRUTH[r] for r in TRUTH], 10)
    y_pred = np.repeat([wrong[r] for r in TRUTH], 10)
    truth = 1.0 - f1_score(y_true, y_pred, average="macro")
    assert np.mean(draws) == pytest.approx(truth, rel=0.1)
    low, high = np.quantile(draws, [0.025, 0.975])
    assert low == 0.0  # resamples without the wrong recording show no difference
    assert low < truth < high
    assert np.all(draws >= 0)


def test_resamples_are_deterministic_and_paired_by_group():
    side = _rows("a", 0, TRUTH, dict(TRUTH, **{"healthy-1": 1}))
    other = _rows("b", 0, TRUTH, TRUTH)
    first, _ = _difference(side, other)
    second, _ = _difference(side, other)
    assert np.array_equal(first, second)


def test_missing_or_mismatched_counts_are_reported_not_guessed():
    side = _rows("a", 0, TRUTH, TRUTH)
    draws, reason = _difference(side, side.assign(sensor="b").iloc[:0])
    assert draws is None and "missing" in reason
    single = {f"{c}-0": i for i, c in enumerate(CLASSES)}
    lone = _rows("a", 0, single, single)
    draws, reason = _difference(lone, lone.assign(sensor="b"))
    assert draws is None and "1 test recording" in reason
