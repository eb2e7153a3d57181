"""Runs are submitted longest first, locally and on Dask, and the order changes no result."""

from __future__ import annotations

import json
import time
from dataclasses import replace

import pandas as pd

from sdt_framework.bench.execute import DaskExecutor
from sdt_framework.bench.featurise import FeatureJob
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.bench.schedule import (
    TIMINGS_FILE,
    longest_first,
    read_factors,
    recordings_longest_first,
)
from sdt_framework.bench.tasks import plan_tasks


def _tasks(small_config, registry, tmp_path, **changes):
    plan = plan_benchmark(small_config(**changes), registry)
    features = run_benchmark(plan, tmp_path / "features-only").features
    return [task for _, task in plan_tasks(plan, features, set())]


def test_mlp_on_the_largest_training_sets_comes_first(small_config, registry, tmp_path):
    """Expectation from the classifiers, not from the cost model: an MLP fit costs more than
    logistic regression, which costs more than kNN (no fit), on the same data; more training
    windows cost more. The scenarios train on different numbers of runs, so training sizes
    differ: forward trains on fewer runs than interpolation."""
    tasks = _tasks(small_config, registry, tmp_path, classifiers=["knn", "lr", "mlp"])
    order = longest_first(tasks, {})
    names = [t.classifier.name for t in order]
    sizes = [len(t.y_train) for t in order]
    n = len(tasks) // 3
    assert names == ["mlp"] * n + ["lr"] * n + ["knn"] * n
    assert len(set(sizes[:n])) > 1, "the test needs training sets of different sizes"
    for start in (0, n):  # within mlp and lr: largest training set first (kNN has no fit)
        assert sizes[start : start + n] == sorted(sizes[start : start + n], reverse=True)
    assert sizes[0] == max(sizes)
    # equal expected times keep the plan's order (stable): the keys of the first
    # classifier's equal-size runs appear as in the plan
    first = [t.key for t in tasks if t.classifier.name == "mlp" and len(t.y_train) == sizes[0]]
    assert [t.key for t in order[: len(first)]] == first


def test_what_previous_runs_took_reorders_classifiers(small_config, registry, tmp_path):
    """A classifier measured 1000 times slower than modelled goes first."""
    tasks = _tasks(small_config, registry, tmp_path, classifiers=["knn", "lr"])
    order = longest_first(tasks, {"knn": 1000.0})
    assert {t.classifier.name for t in order[: len(tasks) // 2]} == {"knn"}


def test_a_benchmark_records_its_run_times_in_the_cache(small_config, registry, tmp_path):
    config = small_config()
    run_benchmark(plan_benchmark(config, registry), tmp_path / "out")
    factors = read_factors(config.cache_dir)
    assert set(factors) == {"lr", "knn"} and all(v > 0 for v in factors.values())
    (tmp_path / "cache" / TIMINGS_FILE).write_text("not json")
    assert read_factors(config.cache_dir) == {}  # a damaged file only loses the order


def test_larger_recordings_are_featurised_first(small_config, registry):
    plan = plan_benchmark(small_config(), registry)
    recs = plan.recordings
    longer = replace(recs[1], n_acquisitions=recs[1].n_acquisitions + 3)
    jobs = [FeatureJob(r, *[None] * 8) for r in (recs[0], longer, recs[2])]
    assert [j.recording for j in recordings_longest_first(jobs)] == [longer, recs[0], recs[2]]


def _started(item: int) -> tuple[int, float]:
    start = time.monotonic()
    time.sleep(0.02)
    return item, start


def test_dask_starts_tasks_in_the_order_given():
    """One worker thread: tasks start exactly in the order given (each carries a priority
    from its place, so the order does not rest on how the scheduler orders equal ones)."""
    from distributed import Client, LocalCluster

    with (
        LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=":0")
        as cluster,
        Client(cluster) as client,
    ):  # fmt: skip
        items = list(range(40))
        done = list(DaskExecutor(client).map_unordered(_started, items))
    assert [item for item, _ in sorted(done, key=lambda d: d[1])] == items


def test_order_changes_no_result(small_config, registry, tmp_path):
    """jobs=2 in the reverse of the usual order (learned factors say so) gives the results
    of jobs=1 bit for bit, MLP and random forest included."""
    classifiers = ["lr", "rf", "mlp"]
    cache = tmp_path / "cache2"
    cache.mkdir()
    (cache / TIMINGS_FILE).write_text(json.dumps({"lr": 1e6, "rf": 1e3, "mlp": 1e-6}))
    two = small_config(classifiers=classifiers, jobs=2, cache_dir=str(cache))
    one = small_config(classifiers=classifiers, jobs=1)
    a = tidy(run_benchmark(plan_benchmark(two, registry), tmp_path / "two").runs)[0]
    b = tidy(run_benchmark(plan_benchmark(one, registry), tmp_path / "one").runs)[0]
    pd.testing.assert_frame_equal(a.drop(columns="fit_seconds"), b.drop(columns="fit_seconds"))
