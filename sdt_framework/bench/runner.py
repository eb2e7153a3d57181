"""The benchmark orchestrator: plan, featurise, classify, collect.

For each machine x scenario x sensor x classifier x repetition (SPEC section
7): degrade (noise seeded per repetition), extract features, standardise on
the training runs only, fit, predict and score. :func:`plan_benchmark`
resolves and checks everything before any work starts; :func:`run_benchmark`
executes the plan locally or on Dask, resuming from the per-run files already
in the output folder.
"""

from __future__ import annotations

import hashlib
import json
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from ..data.cache import default_cache_dir
from ..data.open import open_dataset
from ..data.recording import Dataset, Recording
from ..errors import SDTError
from ..features import resolve_feature_set, samples_for
from ..io import atomic_write_text
from ..registry import Registry
from ..seeding import derive_seed
from ..specs import ClassifierSpec, FeatureSetSpec, SensorSpec
from .classify import RunResult, RunTask, run_classifier
from .config import BenchmarkConfig
from .execute import open_executor
from .featurize import FeatureBlock, FeatureJob, featurize_recording
from .scenarios import Run, check_allocation, load_allocation, rule_allocation

__all__ = ["BenchmarkResult", "Plan", "plan_benchmark", "run_benchmark"]

Progress = Callable[[str, int, int], None]


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


@dataclass
class BenchmarkResult:
    """What a benchmark produced, plus counters for caching and resuming."""

    plan: Plan
    runs: list[RunResult]
    features: pd.DataFrame
    features_computed: int = 0
    features_cached: int = 0
    runs_computed: int = 0
    runs_resumed: int = 0
    seconds: dict[str, float] = field(default_factory=dict)


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
    sensors = _pick(config.sensors, registry.sensor, registry.sensors())
    classifiers = _pick(config.classifiers, registry.classifier, registry.classifiers())
    feature_set = resolve_feature_set(registry, config.features)
    dataset = _open(config, registry)
    recordings = dataset.recordings()
    if not recordings:
        raise SDTError(f"dataset {dataset.name!r} has no usable recordings")
    machines = _select(config.machines, {r.machine for r in recordings}, "machine(s)")
    channels = _select(config.channels, {r.channel for r in recordings}, "channel(s)")
    recordings = [r for r in recordings if r.machine in machines and r.channel in channels]
    _check_rates(recordings, sensors, config)

    runs = sorted(
        {Run(r.machine, r.run, r.condition, r.severity) for r in recordings},
        key=lambda r: (r.machine, r.run),
    )
    if config.allocation:
        allocation = load_allocation(config.allocation, runs)
        allocation = allocation[allocation["scenario"].isin(config.scenarios)]
    else:
        allocation = rule_allocation(runs, config.scenarios)
    skipped = check_allocation(allocation)
    used = allocation[
        [
            (m, s) not in skipped
            for m, s in zip(allocation["machine"], allocation["scenario"], strict=True)
        ]
    ]
    needed = set(zip(used["machine"], used["run"], strict=True))
    recordings = [r for r in recordings if (r.machine, r.run) in needed]
    key_source = json.dumps(
        [dataset.name, config.data, config.dataset_options], sort_keys=True, default=str
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
    )


def _open(config: BenchmarkConfig, registry: Registry) -> Dataset:
    """Open the configured dataset; an option its loader does not take is a user error."""
    options = dict(config.dataset_options)
    try:
        if config.dataset:
            spec = registry.dataset(config.dataset)
            if spec.requires_path and not config.data:
                raise SDTError(f"dataset {config.dataset!r} needs --data PATH")
            return spec.loader(config.data, **options)
        return open_dataset(registry, config.data or "synthetic-pump", **options)
    except TypeError as exc:
        if "unexpected keyword argument" not in str(exc):
            raise
        raise SDTError(
            f"dataset_options {sorted(options)} do not fit the dataset "
            f"({config.dataset or config.data or 'synthetic-pump'}): {exc}"
        ) from None


def _check_rates(recordings: list[Recording], sensors: list[SensorSpec], config) -> None:
    for rate in sorted({r.sampling_rate_hz for r in recordings}):
        example = next(r for r in recordings if r.sampling_rate_hz == rate)
        seconds = example.samples_per_acquisition / rate
        for sensor in sensors:
            if sensor.sampling_rate_hz > rate:
                raise SDTError(
                    f"sensor {sensor.name!r} samples at {sensor.sampling_rate_hz:g} Hz, above the "
                    f"data's {rate:g} Hz (e.g. {example.source}); drop it from --sensors or use "
                    f"data recorded at least that fast"
                )
            need = samples_for(config.window_s, sensor.sampling_rate_hz) + samples_for(
                config.settle_s, sensor.sampling_rate_hz
            )
            if seconds * sensor.sampling_rate_hz < need:
                raise SDTError(
                    f"acquisitions of {seconds:g} s are too short for one {config.window_s} s "
                    f"window after {config.settle_s} s settling (e.g. {example.source})"
                )


def _run_key(
    plan: Plan, labels: dict[str, Any], sensor: SensorSpec, clf: ClassifierSpec, part: pd.DataFrame
) -> str:
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
    return hashlib.sha256(json.dumps(parts, sort_keys=True, default=str).encode()).hexdigest()[:24]


def _feature_frame(plan: Plan, blocks: list[FeatureBlock]) -> pd.DataFrame:
    """All feature blocks as one table, in plan order (never in completion order).

    Row order matters: bootstrap samples (rf), minibatches (mlp) and tree
    building (xgb) depend on it, so it must not depend on which worker finished
    first.
    """
    by_id = {r.recording_id: r for r in plan.recordings}
    position = {r.recording_id: i for i, r in enumerate(plan.recordings)}
    sensor_position = {s.name: i for i, s in enumerate(plan.sensors)}
    blocks = sorted(
        blocks, key=lambda b: (position[b.recording_id], sensor_position[b.sensor], b.repeat)
    )
    frames = []
    for b in blocks:
        rec = by_id[b.recording_id]
        frame = pd.DataFrame(b.values, columns=list(plan.feature_set.feature_names))
        meta = {
            "machine": rec.machine,
            "run": rec.run,
            "condition": rec.condition,
            "severity": rec.severity,
            "channel": rec.channel,
            "recording_id": rec.recording_id,
            "sensor": b.sensor,
            "repeat": b.repeat,
        }
        for i, (name, value) in enumerate(meta.items()):
            frame.insert(i, name, value)
        frame.insert(len(meta), "acquisition", b.acquisition)
        frame.insert(len(meta) + 1, "window", b.window)
        frames.append(frame)
    out = pd.concat(frames, ignore_index=True)
    out["severity"] = out["severity"].astype("Int64")
    return out


def _tasks(plan: Plan, features: pd.DataFrame, done: set[str]):
    names = list(plan.feature_set.feature_names)
    config = plan.config
    for (machine, scenario), part in plan.allocation.groupby(["machine", "scenario"], sort=True):
        if (machine, scenario) in plan.skipped:
            continue
        side = dict(zip(part["run"], part["side"], strict=True))
        classes = tuple(sorted(part["condition"].unique()))
        code = {c: i for i, c in enumerate(classes)}
        rows = features[(features["machine"] == machine) & features["run"].isin(side)]
        for (sensor_name, repeat), sub in rows.groupby(["sensor", "repeat"], sort=True):
            is_train = sub["run"].map(side).eq("train").to_numpy()
            x = sub[names].to_numpy()
            y = sub["condition"].map(code).to_numpy()
            sensor = next(s for s in plan.sensors if s.name == sensor_name)
            for clf in plan.classifiers:
                seed = derive_seed(config.seed, "classifier", int(repeat), clf.name)
                labels = {
                    "dataset": plan.dataset.name,
                    "machine": machine,
                    "scenario": scenario,
                    "sensor": sensor_name,
                    "feature_set": plan.feature_set.name,
                    "classifier": clf.name,
                    "repeat": int(repeat),
                    "seed": seed,
                }
                key = _run_key(plan, labels, sensor, clf, part)
                yield (
                    key,
                    RunTask(
                        key,
                        labels,
                        clf,
                        seed,
                        classes,
                        x[is_train],
                        y[is_train],
                        x[~is_train],
                        y[~is_train],
                    )
                    if key not in done
                    else None,
                )


def _load_done(runs_dir: Path) -> dict[str, RunResult]:
    done = {}
    for path in sorted(runs_dir.glob("*.json")):
        data = json.loads(path.read_text())
        if data.get("status") == "ok":
            done[data["key"]] = RunResult(**data)
    return done


def run_benchmark(
    plan: Plan, out_dir: str | Path, progress: Progress | None = None
) -> BenchmarkResult:
    """Execute ``plan``, writing one file per finished run under ``out_dir/runs``.

    Runs already finished in ``out_dir`` (same key) are not redone; failed runs
    are never stored, so a resume retries them.
    """
    config = plan.config
    out_dir = Path(out_dir)
    runs_dir = out_dir / "runs"
    runs_dir.mkdir(parents=True, exist_ok=True)
    report = progress or (lambda stage, done, total: None)
    cache_dir = config.cache_dir or str(default_cache_dir())
    jobs = [
        FeatureJob(
            r,
            plan.dataset_key,
            tuple(plan.sensors),
            plan.feature_set,
            config.repeats,
            config.seed,
            config.window_s,
            config.settle_s,
            cache_dir,
        )
        for r in plan.recordings
    ]
    seconds: dict[str, float] = {}
    with open_executor(config.backend, config.n_jobs(), config.scheduler) as executor:
        start = time.perf_counter()
        blocks: list[FeatureBlock] = []
        report("features", 0, len(jobs))
        for i, result in enumerate(executor.map_unordered(featurize_recording, jobs), 1):
            blocks.extend(result)
            report("features", i, len(jobs))
        seconds["features"] = time.perf_counter() - start
        features = _feature_frame(plan, blocks)

        start = time.perf_counter()
        previous = _load_done(runs_dir)
        planned = list(_tasks(plan, features, set(previous)))
        todo = [task for _, task in planned if task is not None]
        finished = {key: previous[key] for key, task in planned if task is None}
        report("runs", len(finished), len(planned))
        for result in executor.map_unordered(run_classifier, todo):
            if result.status == "ok":
                atomic_write_text(runs_dir / f"{result.key}.json", json.dumps(result.as_dict()))
            finished[result.key] = result
            report("runs", len(finished), len(planned))
        seconds["classify"] = time.perf_counter() - start
    return BenchmarkResult(
        plan,
        [finished[key] for key, _ in planned],
        features,
        features_computed=sum(b.source == "computed" for b in blocks),
        features_cached=sum(b.source == "cached" for b in blocks),
        runs_computed=len(todo),
        runs_resumed=len(planned) - len(todo),
        seconds=seconds,
    )
