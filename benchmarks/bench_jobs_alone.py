"""A benchmark too short for worker processes: the default ``--jobs`` (the command's own
process) against ``--jobs 2`` (two loky workers), as a user runs ``sdt benchmark``.

A local benchmark the estimate puts under 5 s of single-thread work runs without
workers by default (``ALONE_BELOW_SECONDS`` in ``sdt_framework/bench/estimate.py``);
each loky worker imports scipy, pandas and scikit-learn before its first task. Both
runs start from an empty feature cache and give the same results (checked). Wall
seconds, best of ``--repeats``, each run a fresh ``sdt`` process. Usage:

    .venv/bin/python benchmarks/bench_jobs_alone.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd

ARGS = ["--quick", "--machines", "Motor-2", "--classifiers", "lr", "--no-report"]


def _run(folder: Path, name: str, extra: list[str]) -> tuple[float, pd.DataFrame]:
    out, cache = folder / name, folder / f"{name}-cache"
    command = [sys.executable, "-m", "sdt_framework", "benchmark", *ARGS, *extra]
    start = time.perf_counter()
    subprocess.run(
        [*command, "--out", str(out)],
        check=True,
        capture_output=True,
        env={**os.environ, "SDT_CACHE_DIR": str(cache)},
    )
    seconds = time.perf_counter() - start
    return seconds, pd.read_csv(out / "results.csv").drop(columns="fit_seconds")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3, help="runs of each, best kept")
    args = parser.parse_args()
    alone, workers = [], []
    with tempfile.TemporaryDirectory() as folder:
        for k in range(args.repeats):
            seconds, first = _run(Path(folder), f"alone{k}", [])
            alone.append(seconds)
            seconds, second = _run(Path(folder), f"jobs2-{k}", ["--jobs", "2"])
            workers.append(seconds)
            pd.testing.assert_frame_equal(first, second)
    print(f"sdt benchmark {' '.join(ARGS)}: same results")
    print(
        f"default --jobs (this process): {min(alone):.2f} s; --jobs 2 (two loky workers): "
        f"{min(workers):.2f} s ({min(workers) / min(alone):.2f}x)"
    )


if __name__ == "__main__":
    main()
