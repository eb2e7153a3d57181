"""The orchestrator end to end on a small synthetic benchmark."""

from __future__ import annotations

import json
import types

import numpy as np
import pandas as pd
import pytest

from sdt_framework import ClassifierSpec, SDTError, build_registry, hookimpl
from sdt_framework.bench.classify import fit_predict
from sdt_framework.bench.config import load_config
from sdt_framework.bench.output import OUTPUT_FILES, write_outputs
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark


def run(config, registry, out):
    result = run_benchmark(plan_benchmark(config, registry), out)
    return result, tidy(result.runs)[0]


def test_writes_every_output_file(small_config, registry, tmp_path):
    result = run_benchmark(plan_benchmark(small_config(), registry), tmp_path / "out")
    results = write_outputs(result, tmp_path / "out")
    for name in OUTPUT_FILES:
        assert (tmp_path / "out" / name).stat().st_size > 0, name
    # 1 machine x 3 scenarios x 2 sensors x 2 classifiers x 2 repeats
    assert len(results) == 24 and (results["status"] == "ok").all()
    assert pd.read_parquet(tmp_path / "out" / "results.parquet").equals(results)
    allocation = pd.read_csv(tmp_path / "out" / "allocation.csv")
    assert set(allocation["scenario"]) == {"forward", "backward", "interpolation"}
    assert "Experiment A. Forward extrapolation" in (tmp_path / "out" / "table4.md").read_text()
    rerun = load_config(tmp_path / "out" / "config.toml", {})
    # every setting round-trips but the feature-cache folder: this machine's, not the
    # benchmark's (it changes no result; summary.json's machine key names it)
    assert rerun == small_config().model_copy(update={"cache_dir": None})


def test_windows_of_one_run_never_sit_on_both_sides(small_config, registry, tmp_path):
    plan = plan_benchmark(small_config(), registry)
    result = run_benchmark(plan, tmp_path / "out")
    features = result.features
    for (_m, _s), part in plan.allocation.groupby(["machine", "scenario"]):
        train = set(part[part.side == "train"]["run"])
        test = set(part[part.side == "test"]["run"])
        assert not train & test
        assert set(features["run"]) >= train | test
    counts = {
        (r.labels["scenario"], r.labels["sensor"]): (r.n_train, r.n_test) for r in result.runs
    }
    # 2 channels x 2 windows per run: forward trains on healthy 1-2 + 4 classes at level 1
    assert counts[("forward", "adxl345")] == (6 * 4, 5 * 4)


def test_reference_is_deterministic_and_mems_vary(small_config, registry, tmp_path):
    _, results = run(small_config(repeats=3), registry, tmp_path / "out")
    sd = results.groupby(["scenario", "sensor", "classifier"])["macro_f1"].std()
    assert (sd.xs("wilcoxon-786b10", level="sensor") == 0.0).all()
    assert (sd.xs("adxl345", level="sensor").xs("lr", level="classifier") > 0).any()


def test_adding_a_classifier_recomputes_no_features(small_config, registry, tmp_path):
    first, _ = run(small_config(classifiers=["lr"]), registry, tmp_path / "a")
    assert first.features_computed > 0 and first.features_cached == 0
    second, results = run(small_config(), registry, tmp_path / "b")
    assert second.features_computed == 0
    assert second.features_cached == first.features_computed
    assert set(results["classifier"]) == {"lr", "knn"}


def test_resume_redoes_only_missing_runs(small_config, registry, tmp_path):
    out = tmp_path / "out"
    _first, results = run(small_config(), registry, out)
    files = sorted((out / "runs").glob("*.json"))
    assert len(files) == 24
    for path in files[:5]:  # an interruption loses the last runs
        path.unlink()
    second, resumed = run(small_config(), registry, out)
    assert (second.runs_computed, second.runs_resumed) == (5, 19)
    pd.testing.assert_frame_equal(
        results.drop(columns="fit_seconds"), resumed.drop(columns="fit_seconds")
    )


def test_dask_cluster_gives_the_local_results(small_config, registry, tmp_path):
    """Including transfer pairs and node samples, which build their runs from the same
    features."""
    from distributed import LocalCluster

    more = {
        "classifiers": ["lr", "rf"],
        "transfer": ["wilcoxon-786b10 -> adxl345"],
        "channels": ["ch1", "ch2", "ch4"],
        "axes": {"ch1": "x", "ch2": "y", "ch4": "z"},
        "sample": "node",
    }

    with LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster:
        # rf depends on the order of the training rows: results must not depend
        # on which worker finished first.
        config = small_config(
            backend="dask",
            scheduler=cluster.scheduler_address,
            cache_dir=str(tmp_path / "dask-cache"),
            **more,
        )
        _, on_dask = run(config, registry, tmp_path / "dask")
    _, local = run(small_config(**more), registry, tmp_path / "local")
    assert {"wilcoxon-786b10 -> adxl345", "adxl345 @ node"} <= set(local["sensor"])
    pd.testing.assert_frame_equal(
        on_dask.drop(columns="fit_seconds"), local.drop(columns="fit_seconds")
    )


class Boom:
    """A classifier that always fails to fit."""

    def __init__(self, random_state=None):
        self.random_state = random_state

    def fit(self, x, y):
        raise RuntimeError("no convergence today")

    def predict(self, x):
        raise AssertionError("never fitted")


def test_failing_classifier_is_recorded_and_the_rest_completes(small_config, tmp_path):
    plugin = types.ModuleType("boom_plugin")
    spec = ClassifierSpec(name="boom", estimator=f"{__name__}:Boom")
    plugin.register_classifiers = hookimpl(lambda register: register(spec))
    registry = build_registry(plugins=[plugin])
    _result, results = run(small_config(classifiers=["lr", "boom"]), registry, tmp_path / "out")
    failed = results[results["classifier"] == "boom"]
    assert (failed["status"] == "error").all() and len(failed) == 12
    assert (failed["error"] == "RuntimeError: no convergence today").all()
    assert (results[results["classifier"] == "lr"]["status"] == "ok").all()
    # failures are never stored for resuming
    stored = [json.loads(p.read_text()) for p in (tmp_path / "out" / "runs").glob("*.json")]
    assert {s["labels"]["classifier"] for s in stored} == {"lr"}


def test_standardisation_is_fitted_on_training_data_only(registry):
    rng = np.random.default_rng(0)
    x_train = rng.normal(5.0, 2.0, size=(200, 3))
    y_train = (x_train[:, 0] > 5.0).astype(int)
    x_test = rng.normal(5.0, 2.0, size=(50, 3))
    predicted, scaler = fit_predict(registry.classifier("lr"), 0, x_train, y_train, x_test)
    np.testing.assert_allclose(scaler.mean_, x_train.mean(axis=0))
    np.testing.assert_allclose(scaler.scale_, x_train.std(axis=0))
    # A test set shifted by +10 would be re-centred by a scaler fitted on it;
    # with train-only scaling every shifted window lands on the high side.
    shifted, _ = fit_predict(registry.classifier("lr"), 0, x_train, y_train, x_test + 10.0)
    assert shifted.tolist() == [1] * 50 and predicted.tolist() != shifted.tolist()


@pytest.mark.parametrize(
    ("changes", "message"),
    [
        ({"sensors": ["adxl999"]}, "unknown sensor 'adxl999'"),
        ({"classifiers": ["svm"]}, "unknown classifier 'svm'"),
        ({"machines": ["Motor-9"]}, r"unknown machine\(s\) \['Motor-9'\]"),
    ],
)
def test_bad_names_fail_before_any_work(small_config, registry, tmp_path, changes, message):
    with pytest.raises(SDTError, match=message):
        plan_benchmark(small_config(**changes), registry)


def test_negative_repeats_is_rejected_by_the_config():
    with pytest.raises(SDTError, match=r"command line: field 'repeats': Input should be greater"):
        load_config(None, {"repeats": -1})


def test_sensor_faster_than_the_data_is_rejected(small_config, tmp_path):
    fast = tmp_path / "fast.toml"
    fast.write_text(
        'name = "fast"\nsampling_rate_hz = 25600\nfull_scale_g = 50\nadc_bits = 24\n'
        "noise_density_ug_rthz = 10\nmech_cutoff_hz = 30000\nanalog_cutoff_hz = 12000\n"
    )
    registry = build_registry(sensor_files=[fast])
    with pytest.raises(
        SDTError, match="sensor 'fast' samples at 25600 Hz, above the data's 20000 Hz"
    ):
        plan_benchmark(small_config(sensors=["fast"]), registry)
