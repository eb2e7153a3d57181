"""Planning a benchmark: resolve every name and check the data before any work starts.

:func:`plan_benchmark` turns a :class:`~sdt_framework.bench.config.BenchmarkConfig`
into a :class:`Plan`: the dataset opened (metadata only), the recordings of the
selected machines and channels, the sensor, classifier and feature-set specs
from the registry, and the train/test allocation with the (machine, scenario)
pairs that cannot be scored. Unknown names, dataset options the loader does
not take and recordings too short for one window (:mod:`.lengths`) are each one
clear error here, so a sweep never fails half-way; a sensor the data is too slow for is
left out with its reason (:mod:`~sdt_framework.bench.sensor_set`).
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from ..data.open import load_dataset, open_dataset
from ..data.recording import Dataset, Recording
from ..data.speed import select_speeds
from ..errors import SDTError
from ..features import resolve_feature_set
from ..registry import Registry
from ..specs import ClassifierSpec, FeatureContext, FeatureSetSpec, MachineSpec, SensorSpec
from ..stages import StageSpec
from ..stages.units import drawn_stages
from .allocate import plan_allocation
from .config import BenchmarkConfig
from .feature_context import check_order_rates, feature_contexts
from .lengths import check_lengths
from .machines import benchmark_machines
from .node_samples import Node, resolve_nodes
from .nodes import find_nodes, node_sensors
from .sensor_set import default_reference, default_sensor_names, screen_sensors
from .transfer import Transfer, parse_transfers

__all__ = ["Plan", "plan_benchmark"]


@dataclass
class Plan:
    """A fully resolved, checked benchmark."""

    config: BenchmarkConfig
    dataset: Dataset
    dataset_key: str
    recordings: list[Recording]
    sensors: list[SensorSpec]
    classifiers: list[ClassifierSpec]
    feature_set: FeatureSetSpec
    allocation: pd.DataFrame
    skipped: dict[tuple[str, str], str]
    skipped_sensors: dict[str, str] = field(default_factory=dict)
    reference: str = "wilcoxon-786b10"
    #: recording id -> its node's other two axes, for sensors with a node stage (cross-axis)
    nodes: dict[str, tuple[Recording, Recording]] = field(default_factory=dict)
    #: cross-chain pairs (``[benchmark] transfer``), run beside the ordinary runs
    transfers: list[Transfer] = field(default_factory=list)
    #: triaxial nodes classified as one sample per window (``sample = "node"``)
    sample_nodes: list[Node] = field(default_factory=list)
    #: with units: the stages the sensors' tolerances name (a drawn unit adds and binds them)
    stages: dict[str, StageSpec] = field(default_factory=dict)
    #: the machines (speed, bearings, zone table): the dataset's, the config's over them
    machines: dict[str, MachineSpec] = field(default_factory=dict)
    #: a feature set in orders: recording id -> its speed, machine, channel; notes on the speeds
    contexts: dict[str, FeatureContext] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def run_groups(self) -> list[tuple[Transfer, bool]]:
        """(pair, is a transfer) of every group of runs: each sensor trained and tested on
        itself, then each transfer pair; each group runs on channels and on every node."""
        return [(Transfer((s.name,), s.name), False) for s in self.sensors] + [
            (t, True) for t in self.transfers
        ]


def _pick(names: list[str] | None, lookup: Callable[[str], Any], everything: list) -> list:
    return [lookup(n) for n in names] if names else everything


def _select(values: list[str] | None, available: set[str], what: str) -> set[str]:
    if values is None:
        return available
    unknown = sorted(set(values) - available)
    if unknown:
        raise SDTError(f"unknown {what} {unknown}; the data has {sorted(available)}")
    return set(values)


def plan_benchmark(config: BenchmarkConfig, registry: Registry) -> Plan:
    """Resolve every name and check the data before any work starts."""
    sensors = _resolve_sensors(config.sensors, registry) if config.sensors else None
    classifiers = _pick(config.classifiers, registry.classifier, registry.classifiers())
    feature_set = resolve_feature_set(registry, config.features)
    if config.feature_dtype is not None:
        feature_set = feature_set.with_dtype(config.feature_dtype)
    dataset = _open(config, registry)
    recordings = everything = dataset.recordings()
    if not recordings:
        left = dataset.skipped
        first = left[0] if left else None
        why = (
            f": {len(left)} left out, first {first.path}: "
            f"{first.reason.removeprefix(f'{first.path}: ')}"
            if first
            else ""
        )
        notes = f" ({'; '.join(dataset.notes)})" if dataset.notes else ""
        raise SDTError(f"dataset {dataset.name!r} has no usable recordings{why}{notes}")
    machines = _select(config.machines, {r.machine for r in recordings}, "machine(s)")
    channels = _select(config.channels, {r.channel for r in recordings}, "channel(s)")
    recordings = [r for r in recordings if r.machine in machines and r.channel in channels]
    if config.speeds is not None:
        recordings = select_speeds(recordings, config.speeds)
    rates = {r.sampling_rate_hz for r in recordings}
    if sensors is None:
        sensors = _resolve_sensors(default_sensor_names(rates), registry)
    _select(list(config.axes) or None, {r.channel for r in everything}, "channel(s) in axes")
    reference = config.reference or default_reference(rates)
    transfers = _transfers(config, registry, reference, sensors)
    sensors += [
        registry.sensor(n) for n in _chains(transfers) if n not in {s.name for s in sensors}
    ]
    sensors, skipped_sensors = screen_sensors(sensors, recordings, config.axes)
    for pair in transfers:
        for name in (*pair.train, pair.test):
            if name in skipped_sensors:
                raise SDTError(
                    f"transfer {pair.label!r}: {name} cannot simulate this data "
                    f"({skipped_sensors[name]}); drop the pair"
                )

    allocation, skipped = plan_allocation(config, recordings)
    used = allocation[
        [
            (m, s) not in skipped
            for m, s in zip(allocation["machine"], allocation["scenario"], strict=True)
        ]
    ]
    needed = set(zip(used["machine"], used["run"], strict=True))
    recordings = [r for r in recordings if (r.machine, r.run) in needed]
    if not recordings:
        (machine, scenario), reason = sorted(skipped.items())[0]
        raise SDTError(
            f"nothing to benchmark: none of the {len(skipped)} (machine, scenario) pairs can "
            f"be scored (e.g. {machine} / {scenario}: {reason}); each needs a training and a "
            f"test run of every class: add runs, or give an allocation with --allocation"
        )
    check_lengths(recordings, sensors, config.window_s, config.settle_s)
    specs = benchmark_machines(config, dataset)  # a bad machine file: one line, before any run
    recordings, contexts, notes = feature_contexts(feature_set, recordings, specs)
    check_order_rates(feature_set, recordings, contexts, sensors, config.window_s)
    users = node_sensors(sensors, registry)
    nodes = find_nodes(recordings, everything, config.axes, users) if users else {}
    if config.nodes and config.sample != "node":
        raise SDTError(
            "[benchmark] nodes names the nodes of sample = 'node'; set it, or drop nodes"
        )
    sample_nodes = (
        resolve_nodes(config.axes, config.nodes, recordings) if config.sample == "node" else []
    )
    data = None if config.data is None else os.path.abspath(config.data)  # one spelling
    speeds = [] if config.speeds is None else [config.speeds]  # unset: the keys stay
    key_source = json.dumps(
        [dataset.name, data, config.dataset_options, *speeds], sort_keys=True, default=str
    )
    return Plan(
        config,
        dataset,
        hashlib.sha256(key_source.encode()).hexdigest()[:16],
        recordings,
        sensors,
        classifiers,
        feature_set,
        allocation,
        skipped,
        skipped_sensors,
        reference,
        nodes,
        transfers,
        sample_nodes,
        _unit_stages(sensors, registry) if config.units is not None else {},
        specs,
        contexts,
        notes,
    )


def _unit_stages(sensors: list[SensorSpec], registry: Registry) -> dict[str, StageSpec]:
    """The registry's specs of the stages the sensors' tolerances name, by name."""
    return {name: registry.stage(name) for s in sensors for name in drawn_stages(s)}


def _transfers(
    config: BenchmarkConfig, registry: Registry, reference: str, sensors: list[SensorSpec]
) -> list[Transfer]:
    if not config.transfer:
        return []
    return parse_transfers(config.transfer, registry.sensor, reference, [s.name for s in sensors])


def _chains(transfers: list[Transfer]) -> list[str]:
    """Every chain the pairs name, in order of first mention."""
    return list(dict.fromkeys(n for t in transfers for n in (*t.train, t.test)))


def _resolve_sensors(names: list[str], registry: Registry) -> list[SensorSpec]:
    """Resolve every name; two names for one sensor (``adxl355``, ``adxl355[range=2g]``) fail."""
    sensors = [registry.sensor(name) for name in names]
    seen: dict[str, str] = {}
    for name, sensor in zip(names, sensors, strict=True):
        if sensor.name in seen:
            raise SDTError(f"sensors {seen[sensor.name]!r} and {name!r} are both {sensor.name}")
        seen[sensor.name] = name
    return sensors


def _data_path(data: str | None, registry: Registry) -> str | None:
    """``data`` as an absolute path, or a registered dataset's name as given.

    Every recording's file is then named by its absolute path (a manifest's
    relative paths are taken from its folder), which is what each worker
    opens: a Dask worker started in another folder opens the same files.
    """
    if data is None:
        return None
    path = Path(data).expanduser()
    if path.exists():
        return os.path.abspath(path)
    names = sorted(spec.name for spec in registry.datasets())
    if data in names:
        return data
    where = "" if path.is_absolute() else f" (looked for in {os.getcwd()})"
    raise SDTError(
        f"--data {data} does not exist{where}; give an NLN-EMP folder, a .csv/.parquet "
        f"manifest or a registered dataset ({', '.join(names)})"
    )


def _open(config: BenchmarkConfig, registry: Registry) -> Dataset:
    """Open the configured dataset; an option its loader does not take is a user error.

    The config's ``speeds`` reach a loader that takes a ``speeds`` option (NLN-EMP reads
    those speed folders) unless ``dataset_options`` sets its own; a loader without one
    is opened as it is, and the speeds select among its recordings.
    """
    options = dict(config.dataset_options)
    try:
        if config.speeds is not None and "speeds" not in options:
            try:
                return _load(config, registry, {**options, "speeds": list(config.speeds)})
            except TypeError as exc:
                if "'speeds'" not in str(exc):
                    raise
        return _load(config, registry, options)
    except TypeError as exc:
        if "unexpected keyword argument" not in str(exc):
            raise
        raise SDTError(
            f"dataset_options {sorted(options)} do not fit the dataset "
            f"({config.dataset or config.data or 'synthetic-pump'}): {exc}"
        ) from None


def _load(config: BenchmarkConfig, registry: Registry, options: dict[str, Any]) -> Dataset:
    data = _data_path(config.data, registry)
    if config.dataset:
        spec = registry.dataset(config.dataset)
        if spec.requires_path and not data:
            raise SDTError(f"dataset {config.dataset!r} needs --data PATH")
        return load_dataset(registry, spec, data, **options)
    return open_dataset(registry, data or "synthetic-pump", **options)
