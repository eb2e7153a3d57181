"""The benchmark config's ``speeds``: the recordings at those operating speeds, and no others.

An archive in the NLN-EMP layout with Motor-2 at 50, 75 and 100 % (the
synthetic pump's 100 % files copied under the other folders, named as the
archive names them). Left out, ``speeds`` changes nothing: the paper's
protocol reads the paper's speed, with the run names and the dataset key it
had (the feature cache and resumed runs stay valid).
"""

from __future__ import annotations

import shutil

import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework import SDTError
from sdt_framework.bench.runner import plan_benchmark
from sdt_framework.data import write_nln_emp


@pytest.fixture(scope="module")
def archive(tmp_path_factory):
    root = tmp_path_factory.mktemp("nln")
    pump = open_synthetic(None, duration=1.5, machines=["Motor-2"], channels=["ch1"])
    write_nln_emp(pump, root)
    motor = root / "Vibration" / "Motor-2"
    for speed in ("50", "75"):
        for file in (motor / "100").rglob("*.csv"):
            target = motor / speed / file.parent.name / file.name.replace("_100_", f"_{speed}_")
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(file, target)
    return root


def test_speeds_select_the_recordings_at_those_speeds(small_config, registry, archive):
    config = small_config(data=str(archive), dataset_options={}, channels=["ch1"])
    default = plan_benchmark(config, registry)
    assert {r.speed for r in default.recordings} == {"100"}
    assert {r.speed_rpm for r in default.recordings} == {1480.0}
    assert "healthy 1" in {r.run for r in default.recordings}  # the paper's run names

    chosen = plan_benchmark(config.model_copy(update={"speeds": [50.0, 100.0]}), registry)
    assert {(r.speed, r.speed_rpm) for r in chosen.recordings} == {("50", 740.0), ("100", 1480.0)}
    runs = {r.run for r in chosen.recordings}
    assert {"50/healthy 1", "100/healthy 1"} <= runs  # one run per speed folder, not merged
    assert len(chosen.recordings) == 2 * len(default.recordings)
    assert chosen.dataset_key != default.dataset_key
    again = plan_benchmark(config.model_copy(update={"speeds": None}), registry)
    assert again.dataset_key == default.dataset_key  # unset: the key the paper's runs had


def test_a_speed_the_data_lacks_is_one_line_naming_what_it_has(small_config, registry, archive):
    config = small_config(
        data=str(archive), dataset_options={"speeds": "all"}, channels=["ch1"], speeds=[60.0]
    )
    with pytest.raises(SDTError) as error:
        plan_benchmark(config, registry)
    assert str(error.value) == (
        "speeds: no recording at 60; the data has Motor-2 50, Motor-2 75, Motor-2 100 "
        "(machine and speed label, % of rated where it differs)"
    )


def test_a_dataset_without_a_speeds_option_is_selected_by_its_labels(registry, tmp_path):
    """A manifest has no speeds option: ``speeds`` keeps the rows whose speed label matches."""
    import numpy as np

    from sdt_framework.bench.config import BenchmarkConfig

    rows = ["path,sampling_rate_hz,machine,condition,severity,recording_id,channel,speed"]
    for speed in ("50", "100"):
        for run, condition, level in (
            ("h1", "healthy", ""), ("h2", "healthy", ""), ("h3", "healthy", ""),
            ("f1", "fault", "1"), ("f2", "fault", "2"), ("f3", "fault", "3"),
        ):  # fmt: skip
            name = f"{speed}-{run}.npy"
            np.save(tmp_path / name, np.zeros(20_000))
            rows.append(f"{name},20000,m,{condition},{level},{speed}/{run},ch1,{speed}")
    manifest = tmp_path / "m.csv"
    manifest.write_text("\n".join(rows) + "\n", encoding="utf-8")
    config = BenchmarkConfig(data=str(manifest), speeds=[100.0], cache_dir=str(tmp_path / "c"))
    plan = plan_benchmark(config, registry)
    assert {r.speed for r in plan.recordings} == {"100"} and plan.recordings
    with pytest.raises(SDTError, match=r"^speeds: no recording at 75; the data has m 50, m 100"):
        plan_benchmark(config.model_copy(update={"speeds": [75.0]}), registry)


def test_the_synthetic_pumps_speeds_option_is_reached(small_config, registry):
    """The synthetic pump generates Motor-2 at the speeds asked (its ``speeds`` option)."""
    plan = plan_benchmark(small_config(speeds=[50.0]), registry)
    assert {(r.speed, r.speed_rpm) for r in plan.recordings} == {("50", 740.0)}
