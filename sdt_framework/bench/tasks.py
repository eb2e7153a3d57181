"""The classifier runs of a plan: which windows train and test each one, and its key.

For every machine x scenario (its train/test split by physical run) and every
sample set, each (sensor, unit, repetition, classifier) is one run:

- **channel** samples (the paper's): every channel's windows;
- **node** samples (``sample = "node"``): one row per window per node, its
  axes' features concatenated (:mod:`.node_samples`), labelled ``S @ NODE``;
- **transfer** pairs (:mod:`.transfer`): trained on one chain's windows of
  the training runs, tested on another's of the test runs, for either kind
  of sample, labelled ``TRAIN -> TEST``.

A run's key hashes everything that decides its result, so a resume reuses a
stored run exactly when nothing about it changed. Ordinary channel runs keep
the key they always had (no label or key part is added for them).
"""

from __future__ import annotations

import hashlib
import json
from typing import Any, NamedTuple

import numpy as np
import pandas as pd

from ..seeding import derive_seed
from ..specs import SensorSpec
from .classify import RunTask
from .node_samples import node_frame
from .plan import Plan
from .transfer import Transfer

__all__ = ["plan_tasks", "run_key"]

Arrays = dict[tuple, tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]


def run_key(
    plan: Plan,
    labels: dict[str, Any],
    sensor: SensorSpec,
    clf: Any,
    part: pd.DataFrame,
    extra: list[Any] | None = None,
) -> str:
    """The run's identity: data, labels, specs, windowing and split (``extra``: more parts)."""
    parts = [
        plan.dataset_key,
        labels,
        sensor.content_hash(),
        clf.content_hash(),
        plan.feature_set.content_hash(),
        plan.config.window_s,
        plan.config.settle_s,
        part[["run", "side"]].to_numpy().tolist(),
    ]
    if plan.config.axes:  # channel -> axis changes a part's noise (left out when unset: keys stay)
        parts.append(sorted(plan.config.axes.items()))
    parts += extra or []
    return hashlib.sha256(json.dumps(parts, sort_keys=True, default=str).encode()).hexdigest()[:24]


def _arrays(rows: pd.DataFrame, names: list[str], side: dict, code: dict, units: bool) -> Arrays:
    """(sensor, unit, repeat) -> (x, y, is_train, recording ids), rows in table order."""
    by = ["sensor", "unit", "repeat"] if units else ["sensor", "repeat"]
    out: Arrays = {}
    for group, sub in rows.groupby(by, sort=True):
        key = (group[0], group[1] if units else -1, group[-1])
        out[key] = (
            sub[names].to_numpy(),
            sub["condition"].map(code).to_numpy(),
            sub["run"].map(side).eq("train").to_numpy(),
            sub["recording_id"].to_numpy(),
        )
    return out


def _sample_sets(plan: Plan, features: pd.DataFrame) -> list[tuple[str | None, pd.DataFrame, list]]:
    """(node name or None for channels, feature table, its feature columns in order); each
    node's table is built once, for every machine and scenario."""
    names = list(plan.feature_set.feature_names)
    sets: list[tuple[str | None, pd.DataFrame, list]] = [(None, features, names)]
    for node in plan.sample_nodes:
        table = node_frame(features, node, names)
        sets.append((node.name, table, [c for c in table.columns if ":" in c]))
    return sets


def plan_tasks(plan: Plan, features: pd.DataFrame, done: set[str]):
    """(key, RunTask or None when ``done`` holds the key) for every run of ``plan``."""
    units = plan.config.units is not None
    specs = {s.name: s for s in plan.sensors}
    pairs = plan.run_groups()
    sample_sets = _sample_sets(plan, features)
    for (machine, scenario), part in plan.allocation.groupby(["machine", "scenario"], sort=True):
        if (machine, scenario) in plan.skipped:
            continue
        side = dict(zip(part["run"], part["side"], strict=True))
        classes = tuple(sorted(part["condition"].unique()))
        code = {c: i for i, c in enumerate(classes)}
        base = {"dataset": plan.dataset.name, "machine": machine, "scenario": scenario}
        for node, table, names in sample_sets:
            rows = table[(table["machine"] == machine) & table["run"].isin(side)]
            arrays = _arrays(rows, names, side, code, units)
            for sensor_name, unit, repeat in sorted(arrays):
                for pair, is_transfer in pairs:
                    if pair.test == sensor_name:
                        run = Run(pair, is_transfer, node, unit, repeat)
                        yield from _runs(plan, part, arrays, run, classes, specs, base, done)


class Run(NamedTuple):
    """What one group of runs (one per classifier) trains and tests on."""

    pair: Transfer
    is_transfer: bool
    node: str | None
    unit: int
    repeat: int


def _runs(plan: Plan, part: pd.DataFrame, arrays: Arrays, run: Run, classes: tuple[str, ...],
          specs: dict[str, SensorSpec], base: dict[str, Any], done: set[str]):  # fmt: skip
    """The runs of one (pair, sample set, unit, repetition), one per classifier."""
    config = plan.config
    pair, node = run.pair, run.node
    x_test, y_test, train_mask, rids = arrays[(pair.test, run.unit, run.repeat)]
    trains = [arrays[(name, run.unit, run.repeat)] for name in pair.train]
    x_train = np.concatenate([t[0][t[2]] for t in trains])
    y_train = np.concatenate([t[1][t[2]] for t in trains])
    label = pair.label if run.is_transfer else pair.test
    extra: list[Any] = []
    if run.is_transfer:
        extra += [specs[name].content_hash() for name in pair.train]
    if node is not None:
        label = f"{label} @ {node}"
        extra += [n.channels for n in plan.sample_nodes if n.name == node]
    for clf in plan.classifiers:
        seed = derive_seed(config.seed, "classifier", int(run.repeat), clf.name)
        labels = {**base, "sensor": label, "feature_set": plan.feature_set.name,
                  "classifier": clf.name, "repeat": int(run.repeat), "seed": seed}  # fmt: skip
        if config.units is not None:  # nominal runs keep their keys
            labels["unit"] = int(run.unit)
        if run.is_transfer or node is not None:
            labels |= {"train_sensor": pair.train_label, "test_sensor": pair.test}
        if node is not None:
            labels["node"] = node
        key = run_key(plan, labels, specs[pair.test], clf, part, extra)
        yield key, None if key in done else RunTask(
            key, labels, clf, seed, classes, x_train, y_train, x_test[~train_mask],
            y_test[~train_mask], rids[~train_mask],
        )  # fmt: skip
