"""Synthetic runs read channel by channel, twice: runs kept for the process, against a run
generated at every read.

A benchmark reads a run one channel (one recording) at a time; a worker of ``--jobs N``
gets each recording with its own copy of the dataset, and a notebook, a sweep or a second
benchmark reads the same runs again. sdt keeps the generated runs for the process
(``plugins/datasets/synthetic_pump/kept.py``, up to 64 MB); the plain way generates the
run at every read, what a worker did before. Both read every recording of the quick
Motor-2 data (15 runs, 5 channels, 4 s) from a pickled copy, twice, and get the same
samples (checked). Usage:

    .venv/bin/python benchmarks/bench_kept_runs.py [--duration 4]
"""

from __future__ import annotations

import argparse
import pickle
import time

import numpy as np
from sdt_plugins.datasets.synthetic_pump.dataset import open_synthetic
from sdt_plugins.datasets.synthetic_pump.generate import generate_run

CHANNELS = ("ch1", "ch2", "ch3", "ch4", "ch5")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--duration", type=float, default=4.0, help="seconds per acquisition")
    args = parser.parse_args()
    recordings = open_synthetic(duration=args.duration, machines="Motor-2").recordings()
    start = time.perf_counter()
    ours = [pickle.loads(pickle.dumps(r)).load() for _ in range(2) for r in recordings]
    kept = time.perf_counter() - start
    start = time.perf_counter()
    plain = []
    for _ in range(2):
        for r in recordings:
            condition, level = r.run.rsplit(" ", 1)
            run = generate_run(
                r.machine, condition, int(level), channels=CHANNELS, acquisitions=1,
                duration_s=args.duration, seed=0, speed=float(r.speed),
            )  # fmt: skip
            plain.append(run[r.channel])
    each = time.perf_counter() - start
    for got, want in zip(ours, plain, strict=True):
        np.testing.assert_array_equal(got, want)
    print(f"{len(recordings)} recordings of {args.duration:g} s read twice, same samples")
    print(f"runs kept: {kept:.2f} s; a run generated at every read: {each:.2f} s "
          f"({each / kept:.1f}x)")  # fmt: skip


if __name__ == "__main__":
    main()
