"""Benchmark configuration: the quick preset per data source, dataset options, file data."""

from __future__ import annotations

import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework import SDTError
from sdt_framework.bench.config import load_config
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.data import write_nln_emp


def test_quick_on_the_synthetic_pump_shortens_acquisitions():
    config = load_config(None, {"quick": True})
    assert config.repeats == 2 and config.dataset_options == {"duration": 4.0}


def test_quick_on_an_nln_emp_folder_keeps_one_measurement_per_run(tmp_path):
    config = load_config(None, {"quick": True, "data": str(tmp_path)})
    assert config.repeats == 2 and config.dataset_options == {"max_acquisitions": 5}


def test_quick_stays_under_explicit_settings(tmp_path):
    path = tmp_path / "c.toml"
    path.write_text("[benchmark]\nrepeats = 3\ndataset_options = { duration = 2.0 }\n")
    config = load_config(path, {"quick": True})
    assert config.repeats == 3 and config.dataset_options == {"duration": 2.0}
    assert load_config(path, {"quick": True, "repeats": 4}).repeats == 4


def test_an_option_the_dataset_does_not_take_is_one_clear_error(small_config, registry):
    config = small_config(dataset_options={"durations": 2.0})
    with pytest.raises(SDTError, match=r"dataset_options \['durations'\] do not fit the dataset"):
        plan_benchmark(config, registry)


def test_benchmark_on_files_in_the_nln_emp_layout(small_config, registry, tmp_path):
    synthetic = open_synthetic(None, duration=1.5, machines=["Motor-2"], channels=["ch1"])
    write_nln_emp(synthetic, tmp_path / "nln")
    config = small_config(data=str(tmp_path / "nln"), dataset_options={}, channels=["ch1"])
    plan = plan_benchmark(config, registry)
    assert plan.dataset.name == "nln-emp" and len(plan.recordings) == 15
    results = tidy(run_benchmark(plan, tmp_path / "out").runs)[0]
    assert (results["status"] == "ok").all() and len(results) == 24
    # The same signals read from CSV give the reference chain the same features as
    # generated in memory, up to the CSV's 6 significant digits: equal scores.
    direct = small_config(channels=["ch1"], sensors=["wilcoxon-786b10"], classifiers=["lr"])
    in_memory = tidy(run_benchmark(plan_benchmark(direct, registry), tmp_path / "o2").runs)[0]
    from_files = results[(results.sensor == "wilcoxon-786b10") & (results.classifier == "lr")]
    assert from_files["macro_f1"].round(2).tolist() == in_memory["macro_f1"].round(2).tolist()


def test_an_edited_data_file_is_featurised_again(small_config, registry, tmp_path):
    synthetic = open_synthetic(None, duration=1.5, machines=["Motor-2"], channels=["ch1"])
    files = write_nln_emp(synthetic, tmp_path / "nln")
    config = small_config(
        data=str(tmp_path / "nln"),
        dataset_options={},
        channels=["ch1"],
        sensors=["wilcoxon-786b10"],
        classifiers=["lr"],
        repeats=1,
    )
    first = run_benchmark(plan_benchmark(config, registry), tmp_path / "a")
    assert first.features_computed == 15 and first.features_cached == 0
    again = run_benchmark(plan_benchmark(config, registry), tmp_path / "b")
    assert again.features_computed == 0 and again.features_cached == 15
    edited = files[0]  # a real edit: one sample of one acquisition changes
    lines = edited.read_text().splitlines()
    time_value, *values = lines[1000].split(",")
    lines[1000] = ",".join([time_value, "0.5", *values[1:]])
    edited.write_text("\n".join(lines) + "\n")
    third = run_benchmark(plan_benchmark(config, registry), tmp_path / "c")
    assert third.features_computed == 1 and third.features_cached == 14
