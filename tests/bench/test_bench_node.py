"""Node samples: one vector per window per triaxial node, split by physical run.

Three channels of the synthetic pump are declared one node (x, y, z); the
structure is what is tested, not the pump's physics. The node table is checked
against the benchmark's own per-channel features, looked up row by row with a
plain loop; the split, against the allocation.
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.bench.node_samples import node_frame
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.bench.tasks import plan_tasks

AXES = {"ch1": "x", "ch2": "y", "ch4": "z"}


@pytest.fixture(scope="module")
def ran(tmp_path_factory, registry):
    from sdt_framework.bench.config import BenchmarkConfig

    from .conftest import SMALL

    folder = tmp_path_factory.mktemp("node")
    config = BenchmarkConfig(
        **{**SMALL, "cache_dir": str(folder / "cache"), "channels": list(AXES), "axes": AXES,
           "sample": "node", "transfer": ["wilcoxon-786b10 -> adxl345"]}
    )  # fmt: skip
    plan = plan_benchmark(config, registry)
    return plan, run_benchmark(plan, folder / "out")


def test_node_features_are_the_axes_vectors_side_by_side(ran):
    plan, result = ran
    names = list(plan.feature_set.feature_names)
    (node,) = plan.sample_nodes
    assert node.channels == ("ch1", "ch2", "ch4")
    table = node_frame(result.features, node, names)
    f = result.features
    assert len(table) * 3 == len(f)
    lookup = {
        (r.run, r.sensor, r.repeat, r.acquisition, r.window, r.channel): r
        for r in f.itertuples(index=False)
    }
    columns = [f"{axis}:{n}" for axis in "xyz" for n in names]
    for i in np.random.default_rng(0).choice(len(table), 25, replace=False):
        row = table.iloc[i]
        expected = []
        for channel in ("ch1", "ch2", "ch4"):
            source = lookup[(row["run"], row["sensor"], row["repeat"], row["acquisition"],
                             row["window"], channel)]  # fmt: skip
            expected += [getattr(source, n) for n in names]
            assert row["condition"] == source.condition
        assert np.array_equal(row[columns].to_numpy(dtype=float), np.array(expected, dtype=float))


def test_a_node_is_never_on_both_sides_of_a_split(ran):
    plan, result = ran
    by_id = result.features.drop_duplicates("recording_id").set_index("recording_id")["run"]
    for _, task in plan_tasks(plan, result.features, set()):
        if task.labels.get("node") != "node":
            continue
        part = plan.allocation[
            (plan.allocation["machine"] == task.labels["machine"])
            & (plan.allocation["scenario"] == task.labels["scenario"])
        ]
        side = dict(zip(part["run"], part["side"], strict=True))
        test_runs = {by_id[r.split("@")[0]] for r in task.test_recordings}
        assert {side[r] for r in test_runs} == {"test"}
        train_windows = sum(
            (result.features["run"] == r).sum() for r, s in side.items() if s == "train"
        ) // (3 * len(plan.sensors) * plan.config.repeats)  # per channel, sensor, repetition
        assert len(task.y_train) == train_windows * len(task.labels["train_sensor"].split("+"))


def test_node_runs_sit_beside_the_channel_runs(ran):
    _, result = ran
    from sdt_framework.bench.results import tidy

    results = tidy(result.runs)[0]
    labels = set(results["sensor"])
    assert {"adxl345", "adxl345 @ node", "wilcoxon-786b10 -> adxl345 @ node"} <= labels
    nodes = results[results["sensor"] == "adxl345 @ node"].set_index(
        ["machine", "scenario", "classifier", "repeat"]
    )
    channels = results[results["sensor"] == "adxl345"].set_index(nodes.index.names)
    assert (channels.loc[nodes.index, "n_test"] == 3 * nodes["n_test"]).all()
    assert (nodes["node"] == "node").all() and channels["node"].isna().all()


def test_the_size_estimate_counts_node_and_transfer_runs(ran):
    from sdt_framework.bench.estimate import estimate

    plan, result = ran
    assert estimate(plan).runs == len(result.runs)


def test_several_nodes_per_run_are_each_their_own_sample_set(small_config, registry, tmp_path):
    axes = {"ch1": "x", "ch2": "y", "ch3": "z", "ch4": "x", "ch5": "y", "ch6": "z"}
    config = small_config(
        dataset_options={"duration": 1.5, "triaxial": True}, channels=list(axes), axes=axes,
        sample="node", nodes={"motor": ["ch1", "ch2", "ch3"], "pump": ["ch4", "ch5", "ch6"]},
        classifiers=["lr"], repeats=1,
    )  # fmt: skip
    plan = plan_benchmark(config, registry)
    assert [(n.name, n.channels) for n in plan.sample_nodes] == [
        ("motor", ("ch1", "ch2", "ch3")), ("pump", ("ch4", "ch5", "ch6"))
    ]  # fmt: skip
    from sdt_framework.bench.results import tidy

    results = tidy(run_benchmark(plan, tmp_path / "out").runs)[0]
    for sensor in ("wilcoxon-786b10", "adxl345"):
        for node in ("motor", "pump"):
            rows = results[results["sensor"] == f"{sensor} @ {node}"]
            assert len(rows) > 0 and (rows["node"] == node).all()
    channel = results[results["sensor"] == "adxl345"].set_index(["scenario"])["n_test"]
    motor = results[results["sensor"] == "adxl345 @ motor"].set_index(["scenario"])["n_test"]
    assert (channel == 6 * motor).all()  # six channels pooled, one vector per node window
