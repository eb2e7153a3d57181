"""Scenario allocation: the SPEC section 5 rule, user tables, and unusable splits."""

from __future__ import annotations

import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework import SDTError
from sdt_framework.bench.scenarios import Run, check_allocation, load_allocation, rule_allocation


@pytest.fixture(scope="module")
def runs() -> list[Run]:
    recordings = open_synthetic(None, duration=1.0).recordings()
    return sorted(
        {Run(r.machine, r.run, r.condition, r.severity) for r in recordings},
        key=lambda r: (r.machine, r.run),
    )


def sides(allocation, machine, scenario, condition):
    part = allocation[
        (allocation.machine == machine)
        & (allocation.scenario == scenario)
        & (allocation.condition == condition)
    ]
    return {side: sorted(part[part.side == side]["run"]) for side in ("train", "test")}


def test_forward_trains_on_lowest_and_tests_on_highest_level(runs):
    allocation = rule_allocation(runs, ["forward"])
    assert sides(allocation, "Motor-4", "forward", "unbalance motor") == {
        "train": ["unbalance motor 1"],
        "test": ["unbalance motor 6"],
    }
    assert sides(allocation, "Motor-2", "forward", "bearing bpfo") == {
        "train": ["bearing bpfo 1"],
        "test": ["bearing bpfo 3"],
    }


def test_backward_is_the_reverse(runs):
    allocation = rule_allocation(runs, ["backward"])
    assert sides(allocation, "Motor-4", "backward", "align angular") == {
        "train": ["align angular 5"],
        "test": ["align angular 1"],
    }


def test_interpolation_tests_the_levels_between(runs):
    allocation = rule_allocation(runs, ["interpolation"])
    assert sides(allocation, "Motor-4", "interpolation", "align angular") == {
        "train": ["align angular 1", "align angular 5"],
        "test": ["align angular 2", "align angular 3", "align angular 4"],
    }


def test_healthy_trains_on_all_but_the_last(runs):
    for scenario in ("forward", "backward", "interpolation"):
        allocation = rule_allocation(runs, [scenario])
        assert sides(allocation, "Motor-4", scenario, "healthy") == {
            "train": ["healthy 1", "healthy 2"],
            "test": ["healthy 3"],
        }


def test_no_run_on_both_sides_and_every_class_on_both(runs):
    allocation = rule_allocation(runs, ["forward", "backward", "interpolation"])
    per_run = allocation.groupby(["machine", "scenario", "run"])["side"].nunique()
    assert (per_run == 1).all()
    assert check_allocation(allocation) == {}


def test_a_class_with_one_level_makes_the_split_unusable():
    runs = [
        Run("M", "healthy 1", "healthy", None),
        Run("M", "healthy 2", "healthy", None),
        Run("M", "coupling 1", "coupling", 1),
        Run("M", "coupling 2", "coupling", 2),
    ]
    problems = check_allocation(rule_allocation(runs, ["forward", "interpolation"]))
    assert problems == {("M", "interpolation"): "no test run for coupling"}


def test_user_allocation_replaces_the_rule(tmp_path, runs):
    table = tmp_path / "alloc.csv"
    table.write_text(
        "machine,scenario,run,side\n"
        "Motor-2,forward,healthy 1,train\nMotor-2,forward,healthy 2,test\n"
        "Motor-2,forward,impeller 2,train\nMotor-2,forward,impeller 3,test\n"
    )
    allocation = load_allocation(table, runs)
    assert sides(allocation, "Motor-2", "forward", "impeller") == {
        "train": ["impeller 2"],
        "test": ["impeller 3"],
    }
    assert set(allocation["severity"].dropna()) == {2, 3}


@pytest.mark.parametrize(
    ("row", "message"),
    [
        ("Motor-2,forward,healthy 1,both", "row 2: side 'both' must be 'train' or 'test'"),
        ("Motor-2,sideways,healthy 1,train", "row 2: unknown scenario 'sideways'"),
        ("Motor-9,forward,healthy 1,train", "row 2: no run 'healthy 1' on machine 'Motor-9'"),
    ],
)
def test_bad_user_allocation_rows(tmp_path, runs, row, message):
    table = tmp_path / "alloc.csv"
    table.write_text(f"machine,scenario,run,side\n{row}\n")
    with pytest.raises(SDTError, match=message):
        load_allocation(table, runs)


def test_user_allocation_toml_and_duplicates(tmp_path, runs):
    table = tmp_path / "alloc.toml"
    entry = '[[allocation]]\nmachine = "Motor-2"\nscenario = "forward"\nrun = "healthy 1"\n'
    table.write_text(entry + 'side = "train"\n' + entry + 'side = "test"\n')
    with pytest.raises(SDTError, match="listed twice"):
        load_allocation(table, runs)
