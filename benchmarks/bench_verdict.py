"""Recording-level bootstrap of `sdt compare`: one matrix product against a plain loop.

A cell of the default protocol on NLN-EMP-like sizes: 10 repetitions, 9
classes, 45 test recordings (9 x 5 channels), 2000 resamples. The plain way
redraws the recordings for each resample, concatenates their windows' labels
and calls sklearn's f1_score per repetition; the verdict package sums the
per-recording confusion counts with one matrix product per side and computes
Macro F1 on all resamples at once. Both use the same draws, so the numbers must
agree. Usage:

    .venv/bin/python benchmarks/bench_verdict.py
"""

from __future__ import annotations

import time

import numpy as np
from sklearn.metrics import f1_score

from sdt_framework.verdict.recordings import macro_f1, resample_counts, stratified_weights

N_REPEATS, N_CLASSES, PER_CLASS, WINDOWS, N_BOOT = 10, 9, 5, 40, 2000
PLAIN_BOOT = 100  # the loop is timed on fewer resamples and scaled


def main() -> None:
    rng = np.random.default_rng(0)
    n_rec = N_CLASSES * PER_CLASS
    strata = np.repeat(np.arange(N_CLASSES), PER_CLASS)
    # predictions per (repeat, recording, window): right 70 % of the time
    truth = np.repeat(strata[None, :, None], N_REPEATS, 0).repeat(WINDOWS, 2)
    noise = rng.integers(0, N_CLASSES, truth.shape)
    predicted = np.where(rng.random(truth.shape) < 0.7, truth, noise)
    cube = np.zeros((N_REPEATS, n_rec, N_CLASSES, N_CLASSES))
    idx = np.indices(truth.shape)
    np.add.at(cube, (idx[0], idx[1], truth, predicted), 1)
    weights = stratified_weights(strata, N_BOOT, np.random.default_rng(1))

    start = time.perf_counter()
    fast = macro_f1(resample_counts(weights, cube))
    fast_s = time.perf_counter() - start

    start = time.perf_counter()
    plain = np.empty((PLAIN_BOOT, N_REPEATS))
    for b in range(PLAIN_BOOT):
        drawn = np.repeat(np.arange(n_rec), weights[b].astype(int))
        for r in range(N_REPEATS):
            plain[b, r] = f1_score(
                truth[r, drawn].ravel(), predicted[r, drawn].ravel(), average="macro"
            )
    plain_s = (time.perf_counter() - start) * N_BOOT / PLAIN_BOOT

    assert np.allclose(plain, fast[:PLAIN_BOOT]), "the two implementations disagree"
    print(
        f"{N_BOOT} resamples x {N_REPEATS} repetitions, {n_rec} recordings, {N_CLASSES} classes: "
        f"matrix product {fast_s * 1e3:.1f} ms, plain loop {plain_s:.1f} s "
        f"(timed on {PLAIN_BOOT} resamples) -> {plain_s / fast_s:.0f}x; results identical"
    )


if __name__ == "__main__":
    main()
