"""Calibrate and check the benchmark time estimate (`sdt_framework.bench.estimate`).

Measures, in this process and on one thread, the CPU time of featurising the
``--quick`` plan (seconds per million input samples per chain draw) and of
every classifier run (least-squares ``a + b * n_train`` per classifier), prints
those constants beside the ones in ``estimate.py``, then runs the ``--quick``
benchmark (empty cache, ``--jobs 1``) as ``sdt benchmark`` runs it
(``bench.run_benchmark_folder``) and prints its estimated and measured wall
time (from the folder's claim to its last output file) and their ratio. CPU
time, not wall time, is used for the constants so that a busy machine does
not inflate them. Usage:

    .venv/bin/python benchmarks/bench_estimate.py
"""

from __future__ import annotations

import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from sdt_framework import build_registry
from sdt_framework.bench import run_benchmark_folder, runner
from sdt_framework.bench.classify import run_classifier
from sdt_framework.bench.config import load_config
from sdt_framework.bench.estimate import FEATURE_SECONDS_PER_MSAMPLE, RUN_SECONDS
from sdt_framework.bench.featurise import FeatureJob, featurise_recording
from sdt_framework.bench.tasks import plan_tasks


def main() -> None:
    warnings.simplefilter("ignore")
    registry = build_registry()
    with tempfile.TemporaryDirectory() as tmp:
        config = load_config(None, {"quick": True, "jobs": 1, "report": False})
        plan = runner.plan_benchmark(config, registry)
        jobs = [
            FeatureJob(r, plan.dataset_key, tuple(plan.sensors), plan.feature_set,
                       config.repeats, config.seed, config.window_s, config.settle_s, None)
            for r in plan.recordings
        ]  # fmt: skip
        start = time.process_time()
        blocks = [b for job in jobs for b in featurise_recording(job).blocks]
        feature_cpu = time.process_time() - start
        computed = {(b.recording_id, b.sensor, b.repeat) for b in blocks if b.source == "computed"}
        by_id = {r.recording_id: r for r in plan.recordings}
        msamples = (
            sum(
                by_id[rid].n_acquisitions * by_id[rid].samples_per_acquisition
                for rid, _, _ in computed
            )
            / 1e6
        )
        print(
            f"features: {feature_cpu / msamples:.4f} s per Msample per draw "
            f"(estimate.py: {FEATURE_SECONDS_PER_MSAMPLE})"
        )
        features = runner._feature_frame(plan, blocks)
        times: dict[str, list[tuple[int, float]]] = {}
        for _, task in plan_tasks(plan, features, set()):
            start = time.process_time()
            run_classifier(task)
            cpu = time.process_time() - start
            times.setdefault(task.classifier.name, []).append((len(task.y_train), cpu))
        for name, points in sorted(times.items()):
            n, seconds = np.array(points).T
            a, b = np.linalg.lstsq(np.c_[np.ones_like(n), n], seconds, rcond=None)[0]
            stored = RUN_SECONDS[name]
            print(f"{name:>4}: a = {a:.3f} s, b = {b:.6f} s/window (estimate.py: {stored})")

        out = Path(tmp) / "out"
        config = load_config(None, {"quick": True, "jobs": 1, "report": False,
                                    "cache_dir": str(Path(tmp) / "cache")})  # fmt: skip
        marks: list[float] = []

        def started(plan, size) -> None:  # the folder is claimed: the run starts
            marks.extend((time.perf_counter(), time.process_time()))

        predicted = run_benchmark_folder(config, registry, out, started=started).size.seconds
        measured, cpu = time.perf_counter() - marks[0], time.process_time() - marks[1]
        print(
            f"--quick --jobs 1: estimated {predicted:.1f} s; measured {measured:.1f} s wall "
            f"(ratio {predicted / measured:.2f}), {cpu:.1f} s CPU (ratio {predicted / cpu:.2f}; "
            f"wall exceeds CPU when other programs share the cores)"
        )


if __name__ == "__main__":
    main()
