"""Results depend only on (data, configuration, seed): never on --jobs or the backend.

The cause of the old difference: a fit in the main process (``--jobs 1``) ran
with as many BLAS threads as cores, a fit in a loky or Dask worker with one;
the BLAS summation order changes with the thread count and the MLP's training
amplifies the last-bit differences into other predictions.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
from distributed import LocalCluster
from threadpoolctl import threadpool_info, threadpool_limits

from sdt_framework import build_registry
from sdt_framework.bench.classify import fit_predict
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark

#: A classifier that reports the BLAS and OpenMP threads its fit saw: it predicts class 0
#: with one thread and class 1 with more, so the confusion matrices (and per-class
#: scores) differ if the thread count does.
PROBE = """
import numpy as np
from threadpoolctl import threadpool_info

from sdt_framework import ClassifierSpec, hookimpl


class ThreadProbe:
    def __init__(self, random_state=None):
        self.random_state = random_state

    def fit(self, x, y):
        pools = [i["num_threads"] for i in threadpool_info() if i["user_api"] in ("blas", "openmp")]
        self.label_ = 0 if max(pools) == 1 else 1
        return self

    def predict(self, x):
        return np.full(len(x), self.label_)


@hookimpl
def register_classifiers(register):
    register(ClassifierSpec(name="thread-probe", estimator="thread_probe:ThreadProbe"))
"""

EVERY = ["lr", "knn", "rf", "xgb", "mlp", "thread-probe"]


def test_mlp_predictions_do_not_depend_on_the_callers_blas_threads(registry):
    """A real training set (Motor-4 interpolation, reference sensor, repetition 1 of
    the --quick benchmark) on which the MLP once gave Macro F1 0.63535 in-process
    and 0.63120 in a worker; with 2 BLAS threads allowed by the caller it predicted
    8 of 570 test windows differently from a caller allowing 1."""
    stored = np.load(Path(__file__).parent / "data" / "mlp_threads.npz")
    arguments = (
        int(stored["seed"]),
        stored["x_train"],
        stored["y_train"].astype(int),
        stored["x_test"],
    )
    predictions = []
    for threads in (1, 2):
        with threadpool_limits(limits=threads):
            predictions.append(fit_predict(registry.classifier("mlp"), *arguments)[0])
    np.testing.assert_array_equal(predictions[0], predictions[1])


def test_a_fit_runs_on_one_thread_whatever_the_caller_allows(fake_dist):
    """The suite runs with one thread (tests/conftest.py), so the caller allows two here:
    ``fit_predict`` lowers every BLAS and OpenMP pool to one for the fit, and gives the
    caller's back after."""
    fake_dist("thread-probe", {"thread-probe": "thread_probe"}, {"thread_probe": PROBE})
    registry = build_registry()
    rng = np.random.default_rng(0)
    x, y = rng.normal(size=(20, 3)), np.repeat([0, 1], 10)
    with threadpool_limits(limits=2):
        allowed = {i["num_threads"] for i in threadpool_info()}
        fit_predict(registry.classifier("lr"), 0, x, y, x)  # a fit before the probe's import
        predicted, _ = fit_predict(registry.classifier("thread-probe"), 0, x, y, x)
        after = {i["num_threads"] for i in threadpool_info()}
    assert allowed == after == {2}
    assert (predicted == 0).all()


def test_jobs_1_jobs_2_and_dask_give_identical_results_for_every_classifier(
    fake_dist, small_config, tmp_path
):
    fake_dist("thread-probe", {"thread-probe": "thread_probe"}, {"thread_probe": PROBE})
    registry = build_registry()

    def run(name: str, **changes) -> tuple[pd.DataFrame, ...]:
        config = small_config(
            classifiers=EVERY, repeats=1, cache_dir=str(tmp_path / f"cache-{name}"), **changes
        )
        result = run_benchmark(plan_benchmark(config, registry), tmp_path / name)
        results, per_class, confusion = tidy(result.runs)
        return results.drop(columns="fit_seconds"), per_class, confusion

    one = run("jobs1", jobs=1)
    two = run("jobs2", jobs=2)
    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster:
        dask = run("dask", jobs=2, backend="dask", scheduler=cluster.scheduler_address)
    results = one[0]
    # 3 scenarios x 1 sensor x 1 repeat per classifier, every run scored
    assert (results["status"] == "ok").all() and results.groupby("classifier").size().eq(3).all()
    assert set(results["classifier"]) == set(EVERY)
    for table, on_two, on_dask in zip(one, two, dask, strict=True):
        pd.testing.assert_frame_equal(table, on_two)  # bit-identical, every score
        pd.testing.assert_frame_equal(table, on_dask)
