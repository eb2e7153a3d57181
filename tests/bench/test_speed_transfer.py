"""The speed-transfer scenario's allocation (issue 43), checked against its definition.

Runs at 50, 75 and 100 % speed, each speed with healthy runs h1..h3 and a fault
at levels 1..3. Split within each speed by the forward rule (train: h1, h2 and
level 1; test: h3 and level 3), each fold tested at T has a within-speed arm
``speed T -> T`` and a shift arm ``speed S -> T`` on the same test runs. The
expected sets are written out here from that definition, not read from the code.
"""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from sdt_framework import SDTError
from sdt_framework.bench.allocate import plan_allocation
from sdt_framework.bench.config import BenchmarkConfig
from sdt_framework.data.recording import Recording

SPEEDS = ("50", "75", "100")
RUNS = [("h1", "healthy", None), ("h2", "healthy", None), ("h3", "healthy", None)] + [
    (f"f{level}", "fault", level) for level in (1, 2, 3)
]


def _recording(machine, speed, run, condition, level):
    return Recording(
        dataset="d", machine=machine, speed=speed, condition=condition, severity=level,
        run=f"{speed}/{run}", channel="ch1", recording_id=f"{machine}/{speed}/{run}/ch1",
        sampling_rate_hz=1000.0, units="g", n_acquisitions=1, samples_per_acquisition=8,
        measurement=(0,), source="test", reader=lambda: None,
        speed_percent=float(speed), speed_rpm=14.8 * float(speed),
    )  # fmt: skip


def _recordings(speeds=SPEEDS, machine="m"):
    return [_recording(machine, s, *run) for s in speeds for run in RUNS]


def _config(**changes):
    return BenchmarkConfig(scenarios=["speed-transfer"], **changes)


def _sides(allocation, scenario):
    rows = allocation[allocation["scenario"] == scenario]
    return {side: set(rows.loc[rows["side"] == side, "run"]) for side in ("train", "test")}


def _at(speeds, names):
    return {f"{s}/{n}" for s in speeds for n in names}


def test_leave_one_speed_out_trains_at_the_other_speeds_and_tests_the_same_runs():
    allocation, skipped = plan_allocation(_config(), _recordings())
    assert skipped == {}
    expected = {
        "50": ("75", "100"),
        "75": ("50", "100"),
        "100": ("50", "75"),
    }
    assert set(allocation["scenario"]) == {
        f"speed {'+'.join(train)} -> {test}" for test, train in expected.items()
    } | {f"speed {t} -> {t}" for t in SPEEDS}
    for test, train in expected.items():
        shift = _sides(allocation, f"speed {'+'.join(train)} -> {test}")
        within = _sides(allocation, f"speed {test} -> {test}")
        assert shift["test"] == within["test"] == _at([test], ["h3", "f3"])
        assert shift["train"] == _at(train, ["h1", "h2", "f1"])
        assert within["train"] == _at([test], ["h1", "h2", "f1"])
        # every run carries its speed in its name here: a check independent of the code
        assert {r.split("/")[0] for r in shift["train"]} == set(train)


def test_train_at_100_deploy_at_75_is_one_fold():
    config = _config(speed_transfer={"train": [100], "test": [75]})
    allocation, skipped = plan_allocation(config, _recordings())
    assert skipped == {}
    assert set(allocation["scenario"]) == {"speed 100 -> 75", "speed 75 -> 75"}
    shift, within = _sides(allocation, "speed 100 -> 75"), _sides(allocation, "speed 75 -> 75")
    assert shift["test"] == within["test"] == _at(["75"], ["h3", "f3"])
    assert shift["train"] == _at(["100"], ["h1", "h2", "f1"])
    assert within["train"] == _at(["75"], ["h1", "h2", "f1"])


def test_split_all_trains_and_tests_on_every_run_with_no_within_arm():
    config = _config(speed_transfer={"train": [50, 100], "test": [75], "split": "all"})
    allocation, _ = plan_allocation(config, _recordings())
    assert set(allocation["scenario"]) == {"speed 50+100 -> 75"}
    sides = _sides(allocation, "speed 50+100 -> 75")
    assert sides == {"train": _at(["50", "100"], [r for r, _, _ in RUNS]),
                     "test": _at(["75"], [r for r, _, _ in RUNS])}  # fmt: skip


def test_the_same_speed_on_both_sides_is_refused_in_the_config():
    with pytest.raises(ValidationError, match="'100' is both a training and a test speed"):
        _config(speed_transfer={"train": [50, 100], "test": ["100"]})


def test_a_speed_absent_from_the_data_is_one_line_naming_the_speeds_there():
    config = _config(speed_transfer={"train": [100], "test": [60]})
    with pytest.raises(SDTError) as error:
        plan_allocation(config, _recordings())
    assert str(error.value) == "speed_transfer test: no run at 60; the data has m at 50, 75, 100"


def test_two_spellings_of_one_speed_on_both_sides_are_refused():
    """100 % and 1480 rpm are the same runs: the check runs on the runs chosen, not the text."""
    config = _config(speed_transfer={"train": [100], "test": [1480]})
    with pytest.raises(SDTError, match="both select the runs at 100"):
        plan_allocation(config, _recordings())


def test_data_at_one_speed_is_refused_with_what_it_holds():
    with pytest.raises(SDTError) as error:
        plan_allocation(_config(), _recordings(speeds=("100",)))
    assert "speed transfer needs runs at two speeds or more on one machine" in str(error.value)
    assert "the data has m at 100" in str(error.value)


def test_a_machine_at_one_speed_is_skipped_with_its_reason_beside_one_with_three():
    recordings = _recordings() + _recordings(speeds=("70",), machine="k")
    allocation, skipped = plan_allocation(_config(), recordings)
    assert set(allocation["machine"]) == {"m"}
    assert skipped == {("k", "speed-transfer"): "runs at one speed only (70): speed transfer "
                       "needs two"}  # fmt: skip


def test_speed_transfer_settings_without_the_scenario_are_refused():
    with pytest.raises(ValidationError, match="add it \\(--scenarios speed-transfer\\)"):
        BenchmarkConfig(scenarios=["forward"], speed_transfer={"train": [100], "test": [75]})


def test_a_users_table_row_at_another_speed_than_its_arm_is_refused_naming_the_row(tmp_path):
    table = tmp_path / "alloc.csv"
    table.write_text(
        "machine,scenario,run,side\n"
        "m,speed 100 -> 75,75/h3,test\n"
        "m,speed 100 -> 75,50/h1,train\n"  # trained at 50 in an arm that trains at 100
    )
    with pytest.raises(SDTError) as error:
        plan_allocation(_config(allocation=str(table)), _recordings())
    assert str(error.value) == (
        f"{table}: row 3: run '50/h1' runs at 50; in 'speed 100 -> 75' a train run is at 100"
    )


def test_a_run_whose_channels_name_two_speeds_is_refused():
    recordings = _recordings()
    odd = recordings[0]
    recordings.append(odd.__class__(**{**odd.__dict__, "channel": "ch2", "speed": "51"}))
    with pytest.raises(SDTError, match="run '50/h1' of m has recordings at several speeds"):
        plan_allocation(_config(), recordings)


def test_a_fold_is_scored_whole_an_unscorable_within_arm_takes_its_shift_arm_along(tmp_path):
    """The within arm lacks a training run of the fault; the shift arm alone would be scored
    with nothing to take its loss against, so it is skipped too, saying why."""
    table = tmp_path / "alloc.csv"
    table.write_text(
        "machine,scenario,run,side\n"
        "m,speed 100 -> 75,100/h1,train\nm,speed 100 -> 75,100/f1,train\n"
        "m,speed 100 -> 75,75/h3,test\nm,speed 100 -> 75,75/f3,test\n"
        "m,speed 75 -> 75,75/h1,train\n"
        "m,speed 75 -> 75,75/h3,test\nm,speed 75 -> 75,75/f3,test\n"
    )
    _, skipped = plan_allocation(_config(allocation=str(table)), _recordings())
    assert skipped == {
        ("m", "speed 75 -> 75"): "no training run for fault",
        ("m", "speed 100 -> 75"): "its twin arm 'speed 75 -> 75' is skipped: no training run "
        "for fault",
    }
