"""Classifier runs on one thread: threadpoolctl's cached controller against a library scan
at every fit.

Every run fits with its BLAS and OpenMP pools at one thread (results must not depend on
the thread count: ``tests/reliability/test_bench_jobs.py``). ``threadpool_limits`` scans
every loaded library to find the pools, about 3 ms, at each call; a quick benchmark's
runs fit in 10-100 ms. sdt uses threadpoolctl's cached controller (found again when a
module was imported since). Both loops fit the same logistic regressions on a quick-sized
training set (240 windows x 8 features, 6 classes) and predict the same labels (checked).
Usage:

    .venv/bin/python benchmarks/bench_fit_threads.py [--runs 180]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from sklearn.preprocessing import StandardScaler
from threadpoolctl import threadpool_limits

from sdt_framework import build_registry
from sdt_framework.bench.classify import fit_predict


def plain(spec, seed: int, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """The same fit with ``threadpool_limits`` entered at every call."""
    scaler = StandardScaler().fit(x)
    estimator = spec.build(seed=seed)
    with threadpool_limits(limits=1):
        estimator.fit(scaler.transform(x), y)
        return np.asarray(estimator.predict(scaler.transform(x))).astype(int)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=180, help="fits (a quick benchmark's runs)")
    args = parser.parse_args()
    spec = build_registry().classifier("lr")
    rng = np.random.default_rng(0)
    y = np.repeat(np.arange(6), 40)
    x = rng.normal(size=(y.size, 8)) + y[:, None] * 0.3
    fit_predict(spec, 0, x, y, x), plain(spec, 0, x, y)  # imports and first scans
    start = time.perf_counter()
    ours = [fit_predict(spec, seed, x, y, x)[0] for seed in range(args.runs)]
    cached = time.perf_counter() - start
    start = time.perf_counter()
    theirs = [plain(spec, seed, x, y) for seed in range(args.runs)]
    scanned = time.perf_counter() - start
    for got, want in zip(ours, theirs, strict=True):
        np.testing.assert_array_equal(got, want)
    per = (scanned - cached) / args.runs * 1000
    print(f"{args.runs} logistic regressions, 240 x 8, same predictions")
    print(f"cached controller: {cached:.2f} s; a scan at every fit: {scanned:.2f} s "
          f"({scanned / cached:.1f}x; {per:.1f} ms a run)")  # fmt: skip


if __name__ == "__main__":
    main()
