"""Resampling the test set by recording: how much a difference owes to which recordings were tested.

A run's Macro F1 is one number, but it comes from a handful of test
recordings; another set of recordings of the same machine would have given
another number. ``per_recording.parquet`` keeps each run's confusion counts per
test recording, so the test set can be resampled: recordings are drawn with
replacement within each true class (stratified, so every class keeps its
number of recordings), the drawn recordings' counts are summed, and Macro F1 is
recomputed for both sides of a comparison from the same draw (paired). The
spread of the mean difference over draws gives the recording-level interval.

A recording is one channel of one physical run. Channels of one run are
simultaneous views of the same event, so when a class has a single test run
this interval reflects channel-to-channel variation only, not run-to-run
variation: :class:`RecordingSets` reports both counts so the verdict can say so.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..seeding import rng

__all__ = ["RecordingSets", "TestSet", "macro_f1", "resample_counts", "stratified_weights"]


def macro_f1(confusion: np.ndarray) -> np.ndarray:
    """Macro F1 of confusion matrices ``(..., C, C)`` (rows true, columns predicted).

    Matches ``sklearn.metrics.f1_score(average="macro", zero_division=0)`` on
    the labels behind the counts: a class that is neither present nor
    predicted is left out of the average, a class present or predicted but
    never right scores 0.
    """
    confusion = np.asarray(confusion, dtype=float)
    tp = np.diagonal(confusion, axis1=-2, axis2=-1)
    denominator = confusion.sum(axis=-1) + confusion.sum(axis=-2)  # 2 TP + FP + FN
    present = denominator > 0
    with np.errstate(invalid="ignore", divide="ignore"):
        f1 = np.where(present, 2 * tp / np.where(present, denominator, 1), 0.0)
        return f1.sum(axis=-1) / present.sum(axis=-1)


def stratified_weights(
    strata: np.ndarray, n_boot: int, generator: np.random.Generator
) -> np.ndarray:
    """How often each item is drawn in ``n_boot`` resamples within its stratum.

    Resampling n items with replacement gives multinomial(n, 1/n) counts, so a
    draw is one multinomial per stratum. Returns ``(n_boot, len(strata))``.
    """
    strata = np.asarray(strata)
    weights = np.zeros((n_boot, len(strata)))
    for value in np.unique(strata):  # a handful of classes
        members = np.flatnonzero(strata == value)
        size = len(members)
        weights[:, members] = generator.multinomial(size, np.full(size, 1 / size), n_boot)
    return weights


@dataclass(frozen=True)
class TestSet:
    """The test recordings of one (dataset, machine, scenario) and their resampling weights."""

    recordings: tuple[str, ...]
    classes: tuple[str, ...]
    strata: np.ndarray  # class index of each recording
    weights: np.ndarray  # (n_boot, n_recordings)

    @property
    def smallest_class(self) -> int:
        """Number of recordings of the class with the fewest test recordings."""
        return int(np.unique(self.strata, return_counts=True)[1].min())


class RecordingSets:
    """Per-recording confusion counts of a results table, ready to resample.

    Parameters
    ----------
    per_recording
        Long table: the run columns, ``recording_id``, ``true``, ``predicted``, ``count``.
    group
        Columns that fix a test set (e.g. dataset, machine, scenario): every run
        of a group was tested on the same recordings, so they share one draw.
    n_boot, seed
        Number of resamples and the base seed (each group's draws derive from
        the seed and the group's values, so they do not depend on order).
    """

    def __init__(
        self, per_recording: pd.DataFrame, group: Sequence[str], n_boot: int = 2000, seed: int = 0
    ) -> None:
        self.group = list(group)
        self.n_boot = n_boot
        self.seed = seed
        self._sets: dict[tuple, TestSet] = {}
        frame = per_recording.reset_index(drop=True)
        codes = np.zeros((len(frame), 3), dtype=np.int64)  # recording, true, predicted
        for key, rows in frame.groupby(self.group, sort=False, dropna=False):
            key = key if isinstance(key, tuple) else (key,)
            test = self._make(key, rows)
            self._sets[key] = test
            codes[rows.index, 0] = np.searchsorted(test.recordings, rows["recording_id"])
            for column, name in ((1, "true"), (2, "predicted")):
                codes[rows.index, column] = np.searchsorted(test.classes, rows[name])
        self.frame = frame.assign(_rec=codes[:, 0], _true=codes[:, 1], _pred=codes[:, 2])

    def _make(self, key: tuple, rows: pd.DataFrame) -> TestSet:
        labels = rows.drop_duplicates("recording_id").sort_values("recording_id")
        classes = tuple(sorted(set(rows["true"]) | set(rows["predicted"])))
        strata = np.searchsorted(classes, labels["true"])
        generator = rng(self.seed, "verdict-recordings", *key)
        weights = stratified_weights(strata, self.n_boot, generator)
        return TestSet(tuple(labels["recording_id"]), classes, strata, weights)

    def test_set(self, key: tuple) -> TestSet | None:
        """The test set of group ``key`` (None when no counts were stored for it)."""
        return self._sets.get(key)

    @staticmethod
    def cube(rows: pd.DataFrame, test: TestSet, repeats: Sequence[int]) -> np.ndarray | None:
        """Coded ``rows`` as counts ``(repeat, recording, true, predicted)``; None if incomplete."""
        order = np.asarray(sorted(repeats))
        repeat = rows["repeat"].to_numpy()
        keep = np.isin(repeat, order)
        if len(np.unique(repeat[keep])) < len(order):
            return None
        n_rec, n_cls = len(test.recordings), len(test.classes)
        flat = (
            (np.searchsorted(order, repeat[keep]) * n_rec + rows["_rec"].to_numpy()[keep]) * n_cls
            + rows["_true"].to_numpy()[keep]
        ) * n_cls + rows["_pred"].to_numpy()[keep]
        size = len(order) * n_rec * n_cls * n_cls
        counts = np.bincount(flat, weights=rows["count"].to_numpy(float)[keep], minlength=size)
        return counts.reshape(len(order), n_rec, n_cls, n_cls)

    def mean_difference(
        self, candidate: pd.DataFrame, baseline: pd.DataFrame, key: tuple, repeats: Sequence[int]
    ) -> tuple[np.ndarray | None, str]:
        """Resampled mean (over ``repeats``) Macro F1 difference candidate - baseline.

        ``candidate`` and ``baseline`` are one cell's two sides, as rows of
        :attr:`frame` (coded). Returns ``(n_boot,)`` draws, or None and the reason.
        """
        test = self.test_set(key)
        if test is None:
            return None, "no per-recording counts stored (per_recording.parquet)"
        if test.smallest_class < 2:
            return None, "1 test recording in some class: nothing to resample"
        cubes = [self.cube(side, test, repeats) for side in (candidate, baseline)]
        if cubes[0] is None or cubes[1] is None:
            return None, "per-recording counts missing for some runs (stored by an older version)"
        if not np.array_equal(cubes[0].sum(axis=(0, 3)) > 0, cubes[1].sum(axis=(0, 3)) > 0):
            return None, "the two sides were tested on different recordings"
        f1 = [macro_f1(resample_counts(test.weights, cube)) for cube in cubes]
        return (f1[0] - f1[1]).mean(axis=1), ""


def resample_counts(weights: np.ndarray, cube: np.ndarray) -> np.ndarray:
    """Summed counts ``(n_boot, repeat, C, C)`` of each resample: one matrix product."""
    n_rep, n_rec, n_cls, _ = cube.shape
    flat = cube.transpose(1, 0, 2, 3).reshape(n_rec, n_rep * n_cls * n_cls)
    return (weights @ flat).reshape(len(weights), n_rep, n_cls, n_cls)
