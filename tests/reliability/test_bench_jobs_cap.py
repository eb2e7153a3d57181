"""``--jobs`` far above the cores starts only the processes that can help, and says so.

Before, ``--jobs 1000`` on 2 cores started a loky worker per job (a load of 77,
the machine stopped answering) while the estimate said "2 processes". Now the
pool holds at most two processes per core and one per task; the note says why,
and the estimate counts the processes started (their memory included).
"""

from __future__ import annotations

import os
import sys

from sdt_framework.bench.config import load_config
from sdt_framework.bench.estimate import PROCESS_BYTES, estimate
from sdt_framework.bench.plan import plan_benchmark

from ..helpers import run_watching_loky_workers

ARGS = ["--quick", "--machines", "Motor-2", "--channels", "ch1", "--sensors", "wilcoxon-786b10"]
ARGS += ["--classifiers", "lr", "--no-report"]


def test_jobs_far_above_one_core_start_two_workers(tmp_path):
    """On one core (the command pinned to CPU 0), ``--jobs 12`` starts 2 loky workers."""
    command = [sys.executable, "-m", "sdt_framework", "benchmark", *ARGS, "--jobs", "12"]
    command += ["--out", str(tmp_path / "out"), "--cache-dir", str(tmp_path / "cache")]
    done, seen = run_watching_loky_workers(command, preexec_fn=lambda: os.sched_setaffinity(0, {0}))
    err = done.stderr
    assert done.returncode == 0, err
    assert 1 <= len(seen) <= 2, f"{len(seen)} loky workers started"
    notes = [line for line in err.splitlines() if line.startswith("note:")]
    # 15 recordings, 6 runs: 15 tasks at most at once; 1 core: 2 processes
    assert notes[0].startswith("note: this benchmark is 6 runs and 15 featurised signals")
    assert " on 2 processes (" in notes[0]
    assert notes[1] == (
        "note: --jobs 12: starting 2 processes (1 core here; more than 2 processes per core "
        "only take turns on them)"
    )


def test_the_estimate_counts_the_processes_started(registry, monkeypatch):
    monkeypatch.setattr("sdt_framework.bench.pool.cpu_count", lambda: 2)
    options = {"quick": True, "machines": ["Motor-2"], "channels": ["ch1"], "classifiers": ["lr"]}

    def size(jobs: int):
        return estimate(plan_benchmark(load_config(None, {**options, "jobs": jobs}), registry))

    one, two, many = size(1), size(2), size(1000)
    assert (one.workers, two.workers, many.workers) == (1, 2, 4)  # 2 per core
    # four processes on two cores compute no faster than two; each holds its own memory
    assert many.seconds == two.seconds == one.seconds / 2
    assert two.memory_bytes - one.memory_bytes >= 2 * PROCESS_BYTES
    assert many.memory_bytes - two.memory_bytes >= 2 * PROCESS_BYTES
    # 18 runs, 15 recordings: --jobs 40 on 64 cores starts 18 processes, not 40
    monkeypatch.setattr("sdt_framework.bench.pool.cpu_count", lambda: 64)
    assert size(40).workers == 18
