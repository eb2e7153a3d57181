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

__all__ = ["RecordingSets", "TestSet", "macro_f1", "stratified_weights"]


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
        return int(np.bincount(self.strata).min())


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
        self.frame = per_recording
        self.group = list(group)
        self.n_boot = n_boot
        self.seed = seed
        self._sets: dict[tuple, TestSet | None] = {}
        self._by_group = dict(iter(per_recording.groupby(self.group, sort=False, dropna=False)))

    def test_set(self, key: tuple) -> TestSet | None:
        """The test set of group ``key`` (None when no counts were stored for it)."""
        if key not in self._sets:
            rows = self._by_group.get(key)
            if rows is None or rows.empty:
                self._sets[key] = None
            else:
                labels = rows.drop_duplicates("recording_id").sort_values("recording_id")
                classes = tuple(sorted(set(rows["true"]) | set(rows["predicted"])))
                strata = labels["true"].map({c: i for i, c in enumerate(classes)}).to_numpy()
                generator = rng(self.seed, "verdict-recordings", *key)
                self._sets[key] = TestSet(
                    tuple(labels["recording_id"]),
                    classes,
                    strata,
                    stratified_weights(strata, self.n_boot, generator),
                )
        return self._sets[key]

    def cube(self, rows: pd.DataFrame, test: TestSet, repeats: Sequence[int]) -> np.ndarray | None:
        """Counts as ``(repeat, recording, true, predicted)``; None when a run has none."""
        repeat_index = {r: i for i, r in enumerate(repeats)}
        rows = rows[rows["repeat"].isin(repeat_index)]
        if rows.empty or rows["repeat"].nunique() < len(repeats):
            return None
        recording_index = {r: i for i, r in enumerate(test.recordings)}
        class_index = {c: i for i, c in enumerate(test.classes)}
        rec = rows["recording_id"].map(recording_index)
        if rec.isna().any():
            return None
        n_rec, n_cls = len(test.recordings), len(test.classes)
        flat = (
            (rows["repeat"].map(repeat_index).to_numpy() * n_rec + rec.to_numpy(dtype=int)) * n_cls
            + rows["true"].map(class_index).to_numpy()
        ) * n_cls + rows["predicted"].map(class_index).to_numpy()
        counts = np.bincount(flat, weights=rows["count"].to_numpy(float), minlength=0)
        counts = np.pad(counts, (0, len(repeats) * n_rec * n_cls * n_cls - len(counts)))
        return counts.reshape(len(repeats), n_rec, n_cls, n_cls)

    def mean_difference(
        self, candidate: pd.DataFrame, baseline: pd.DataFrame, key: tuple, repeats: Sequence[int]
    ) -> tuple[np.ndarray | None, str]:
        """Resampled mean (over ``repeats``) Macro F1 difference candidate - baseline.

        ``candidate`` and ``baseline`` are the per-recording rows of one cell's
        two sides. Returns ``(n_boot,)`` draws, or None and the reason.
        """
        test = self.test_set(key)
        if test is None:
            return None, "no per-recording counts stored (per_recording.parquet)"
        if test.smallest_class < 2:
            return None, "1 test recording in some class: nothing to resample"
        cubes = [self.cube(side, test, repeats) for side in (candidate, baseline)]
        if cubes[0] is None or cubes[1] is None:
            return (
                None,
                "per-recording counts missing for some runs (resumed from an older version?)",
            )
        if not np.array_equal(cubes[0].sum(axis=(0, 3)) > 0, cubes[1].sum(axis=(0, 3)) > 0):
            return None, "the two sides were tested on different recordings"
        f1 = [
            macro_f1(np.einsum("bk,rkij->brij", test.weights, cube, optimize=True))
            for cube in cubes
        ]
        return (f1[0] - f1[1]).mean(axis=1), ""
