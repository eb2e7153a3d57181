"""SALib's delta analysis (the lhs design's sensitivity) as explore runs it, and as called plainly.

``sdt explore`` with ``design = "lhs"`` ranks parameters with SALib's delta
measure, which evaluates a Gaussian KDE for every bootstrap sample: thousands
of tiny linear solves. Called plainly, OpenBLAS starts a thread per core for
each; explore runs it with one BLAS thread (``explore.designs._quiet``). Both
are timed in one process on the same 64-point design, and their indices are
checked equal. Usage:

    .venv/bin/python benchmarks/bench_sensitivity.py [--samples 64]
"""

from __future__ import annotations

import argparse
import os
import time
import warnings

import numpy as np
from SALib.analyze import delta
from SALib.sample import latin
from threadpoolctl import threadpool_info

from sdt_framework.explore.designs import _quiet

PROBLEM = {"num_vars": 3, "names": ["rate", "noise", "range"], "bounds": [[0.0, 1.0]] * 3}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=64)
    args = parser.parse_args()
    x = latin.sample(PROBLEM, args.samples, seed=1)
    y = 0.4 + 0.3 * x[:, 1]  # one active parameter, as tests/explore/test_explore_analysis.py
    threads = max((pool["num_threads"] for pool in threadpool_info()), default=1)

    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        plain = delta.analyze(PROBLEM, x, y, seed=1, print_to_console=False)
    t_plain = time.perf_counter() - start

    start = time.perf_counter()
    ours = _quiet(lambda: delta.analyze(PROBLEM, x, y, seed=1, print_to_console=False))
    t_ours = time.perf_counter() - start

    same = np.array_equal(plain["delta_raw"], ours["delta_raw"])
    print(f"SALib delta, {args.samples} points x 3 parameters, {os.cpu_count()} cores")
    print(f"plain call ({threads} BLAS threads)  {t_plain:7.2f} s")
    print(f"explore (1 BLAS thread)     {t_ours:7.2f} s")
    print(f"ratio plain / explore       {t_plain / t_ours:7.1f}x; indices equal: {same}")


if __name__ == "__main__":
    main()
