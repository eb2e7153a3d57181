"""The default ``--jobs`` runs a benchmark too short for worker processes in its own process.

Two loky workers take about 5 CPU-s and 2-4 s to start (each imports scipy, pandas and
scikit-learn): ``sdt benchmark --quick --machines Motor-2 --classifiers lr`` took 5.8 s
with two workers and 3.9 s without. A local benchmark estimated under
``ALONE_BELOW_SECONDS`` of single-thread work now starts none when ``--jobs`` is left at
its default, and its estimate says so and how to start them; a longer one, an explicit
``--jobs`` and a Dask run are unchanged. The results never depend on the processes.
"""

from __future__ import annotations

import os
import sys

import pandas as pd

from sdt_framework.bench.config import load_config
from sdt_framework.bench.estimate import ALONE_BELOW_SECONDS, PROCESS_BYTES, estimate, estimate_like
from sdt_framework.bench.plan import plan_benchmark

from ..helpers import run_watching_loky_workers, sdt_here

TINY = {"quick": True, "machines": ["Motor-2"], "channels": ["ch1"], "classifiers": ["lr"]}
ARGS = ["--quick", "--machines", "Motor-2", "--channels", "ch1", "--classifiers", "lr"]
ARGS += ["--no-report"]


def _size(registry, **options):
    return estimate(plan_benchmark(load_config(None, {**TINY, **options}), registry))


def test_the_estimate_runs_a_short_local_benchmark_alone_by_default(registry, monkeypatch):
    monkeypatch.setattr("sdt_framework.bench.pool.cpu_count", lambda: 2)
    default, two = _size(registry), _size(registry, jobs=2)
    assert two.seconds * 2 < ALONE_BELOW_SECONDS  # tiny: under the bound on one process
    assert (default.alone, default.workers, two.alone, two.workers) == (True, 1, False, 2)
    assert default.seconds == 2 * two.seconds  # all the work on one process
    assert two.memory_bytes - default.memory_bytes >= 2 * PROCESS_BYTES  # no worker held
    assert default.line().endswith(
        "on 1 process; starting worker processes would take longer, --jobs N starts N"
    )
    assert two.line().endswith("on 2 processes")
    # Dask was asked for by name; a sweep's per-point estimate is scaled, not run alone
    assert not _size(registry, backend="dask").alone
    plan = plan_benchmark(load_config(None, TINY), registry)
    assert not estimate_like(plan, plan.sensors[0], 40).alone


def test_a_benchmark_over_the_bound_keeps_its_workers(registry, monkeypatch):
    monkeypatch.setattr("sdt_framework.bench.pool.cpu_count", lambda: 2)
    longer = _size(registry, machines=None, channels=None, classifiers=None)  # --quick: 5
    assert longer.seconds * 2 >= ALONE_BELOW_SECONDS
    assert (longer.alone, longer.workers) == (False, 2)


def test_sdt_benchmark_starts_no_worker_for_it_and_gives_the_workers_results(tmp_path):
    """A real ``sdt benchmark`` (two cores allowed, the default ``--jobs``) starts no loky
    worker; its results equal those of ``--jobs 2``, which does start them."""
    out = tmp_path / "alone"
    command = [sys.executable, "-m", "sdt_framework", "benchmark", *ARGS, "--out", str(out)]
    done, seen = run_watching_loky_workers(
        command,
        env={**os.environ, "SDT_CACHE_DIR": str(tmp_path / "cache")},
        preexec_fn=lambda: os.sched_setaffinity(0, {0, 1}),
    )
    err = done.stderr
    assert done.returncode == 0, err
    assert not seen, f"{len(seen)} loky workers started"
    assert "on 1 process; starting worker processes would take longer" in err
    env = {"SDT_CACHE_DIR": str(tmp_path / "cache-2")}
    done = sdt_here("benchmark", *ARGS, "--jobs", "2", "--out", str(tmp_path / "two"), env=env)
    assert done.returncode == 0, done.stderr
    assert "on 2 processes (" in done.stderr
    tables = [
        pd.read_csv(d / "results.csv").drop(columns="fit_seconds") for d in (out, tmp_path / "two")
    ]
    pd.testing.assert_frame_equal(*tables)
