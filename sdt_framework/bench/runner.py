"""Running a planned benchmark: featurise, classify, collect, resume.

For each machine x scenario x sensor x classifier x repetition (SPEC section
7): degrade (noise seeded per repetition), extract features, standardise on
the training runs only, fit, predict and score. :func:`run_benchmark` executes
a :class:`~sdt_framework.bench.plan.Plan` locally or on Dask, resuming from
the per-run files already in the output folder.

Before any work the scheduler address, the feature cache and the results
folder are checked (:mod:`~sdt_framework.bench.folder`: a folder is resumed
only by the configuration that wrote it). A run is stored the moment it
finishes, atomically; Ctrl-C stops everything with ``KeyboardInterrupt`` and
what was stored stays valid, so running the same configuration again
resumes and gives the results an uninterrupted run would have given.
"""

from __future__ import annotations

import os
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from ..data.cache import default_cache_dir
from ..features.quantise import quantise_features
from ..io import ensure_writable_dir
from .classify import RunResult, run_classifier
from .execute import check_scheduler_address, open_executor
from .featurise import FeatureBlock, FeatureJob, featurise_recording
from .folder import claim_results_folder
from .folder_lock import holds_results_folder, unlock_results_folder
from .plan import Plan, plan_benchmark
from .pool import pool_size
from .saturation import saturation_table
from .schedule import (
    learn_factors,
    longest_first,
    read_factors,
    recordings_longest_first,
    write_factors,
)
from .store import load_finished, store_finished
from .tasks import plan_tasks

__all__ = ["BenchmarkResult", "Plan", "plan_benchmark", "preflight", "run_benchmark"]

Progress = Callable[[str, int, int], None]
Warn = Callable[[str], None]


def _warn(message: str) -> None:
    warnings.warn(message, RuntimeWarning, stacklevel=3)


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
    saturation: pd.DataFrame | None = None  # samples at full scale per (sensor, recording)
    cache_dir: str = ""  # the feature cache used (this machine's)
    #: per phase, the time the workers spent in its tasks, summed (wall x workers at best)
    task_seconds: dict[str, float] = field(default_factory=dict)


def _feature_frame(plan: Plan, blocks: list[FeatureBlock]) -> pd.DataFrame:
    """All feature blocks as one table, in plan order (never in completion order).

    Each block is rounded to the feature set's on-node dtype (float32: left as
    is), so classifiers and features.parquet see what the node would send.

    Row order matters: bootstrap samples (rf), minibatches (mlp) and tree
    building (xgb) depend on it, so it must not depend on which worker finished
    first.
    """
    by_id = {r.recording_id: r for r in plan.recordings}
    position = {r.recording_id: i for i, r in enumerate(plan.recordings)}
    sensor_position = {s.name: i for i, s in enumerate(plan.sensors)}
    blocks = sorted(
        blocks,
        key=lambda b: (position[b.recording_id], sensor_position[b.sensor], b.unit, b.repeat),
    )
    meta = []  # one row per block, repeated below for each of its windows
    for b in blocks:
        rec = by_id[b.recording_id]
        row = {
            "machine": rec.machine,
            "run": rec.run,
            "condition": rec.condition,
            "severity": rec.severity,
            "channel": rec.channel,
            "recording_id": rec.recording_id,
            "sensor": b.sensor,
            "repeat": b.repeat,
        }
        if plan.config.units is not None:  # left out otherwise: features.parquet stays as it was
            row["unit"] = b.unit
        if plan.feature_set.needs_speed:  # text: the speed order features were computed at
            row["speed"] = plan.contexts[rec.recording_id].describe_speed()
        meta.append(row)
    windows = np.array([len(b.values) for b in blocks])
    out = pd.DataFrame.from_records(meta)
    out = out.loc[out.index.repeat(windows)].reset_index(drop=True)
    out["acquisition"] = np.concatenate([b.acquisition for b in blocks])
    out["window"] = np.concatenate([b.window for b in blocks])
    values = [quantise_features(b.values, plan.feature_set, where=b.recording_id) for b in blocks]
    names = list(plan.feature_set.feature_names)
    out = pd.concat([out, pd.DataFrame(np.concatenate(values), columns=names)], axis=1)
    out["severity"] = out["severity"].astype("Int64")
    return out


def preflight(plan: Plan, out_dir: str | Path) -> Path:
    """Every check that needs no computation, then claim ``out_dir``; returns the cache folder.

    A malformed scheduler address, a feature cache or results folder that
    cannot be written, or a results folder that must not be (see
    :func:`~sdt_framework.bench.folder.claim_results_folder`) is an ``SDTError``
    here, before any work. Calling it again for the same plan changes nothing.
    """
    config = plan.config
    if config.backend == "dask" and config.scheduler:
        check_scheduler_address(config.scheduler)
    cache_dir = ensure_writable_dir(
        config.cache_dir or default_cache_dir(), "feature cache", "--cache-dir or SDT_CACHE_DIR"
    )
    claim_results_folder(out_dir, config)
    ensure_writable_dir(Path(out_dir) / "runs", "results folder", "--out")
    return cache_dir


def run_benchmark(
    plan: Plan,
    out_dir: str | Path,
    progress: Progress | None = None,
    warn: Warn | None = None,
    *,
    workers: int | None = None,
) -> BenchmarkResult:
    """Execute ``plan``, writing one file per finished run under ``out_dir/runs``.

    ``workers``: the processes to compute in (1: this one), instead of those ``--jobs``
    gives (the caller's estimate found the plan too short for worker processes).

    Runs already finished in ``out_dir`` (same key) are not redone; failed runs
    are never stored, so a resume retries them. ``warn`` receives one line per
    problem that does not stop the run (a corrupt cache entry, a damaged run
    file); by default it issues a ``RuntimeWarning``. ``out_dir`` is locked
    while it runs (released at the end unless the caller held it before).

    Raises
    ------
    SDTError
        Before any work, from :func:`preflight` (another process running in
        ``out_dir`` included).
    KeyboardInterrupt
        On Ctrl-C; nothing of an unfinished run is stored.
    """
    held = holds_results_folder(out_dir)
    try:
        return _run(plan, out_dir, progress, warn, workers)
    finally:
        if not held:
            unlock_results_folder(out_dir)


def _run(
    plan: Plan,
    out_dir: str | Path,
    progress: Progress | None,
    warn: Warn | None,
    workers: int | None = None,
) -> BenchmarkResult:
    config = plan.config
    out_dir = Path(out_dir)
    report = progress or (lambda stage, done, total: None)
    warn = warn or _warn
    cache_dir = preflight(plan, out_dir)
    runs_dir = out_dir / "runs"
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
            str(cache_dir),
            config.axes.get(r.channel, "x"),
            config.units,
            plan.nodes.get(r.recording_id, ()),
            tuple(plan.stages.values()),
            plan.contexts.get(r.recording_id),
        )
        for r in plan.recordings
    ]
    # Longest first only where processes share the work: one process ends at the same time
    # in any order, and plan order keeps its cheap runs first (what Ctrl-C leaves finished).
    workers = pool_size(config.n_jobs()) if workers is None else workers
    spread = config.backend == "dask" or workers > 1
    if spread:
        jobs = recordings_longest_first(jobs)  # results are re-ordered by plan below
    seconds: dict[str, float] = {}
    task_seconds = {"features": 0.0, "classify": 0.0}
    sources = [r.source for r in plan.recordings]
    with open_executor(
        config.backend, workers, config.scheduler, sources, str(cache_dir)
    ) as executor:
        start = time.perf_counter()
        blocks: list[FeatureBlock] = []
        report("features", 0, len(jobs))
        for i, result in enumerate(executor.map_unordered(featurise_recording, jobs), 1):
            blocks.extend(result.blocks)
            task_seconds["features"] += result.seconds
            for note in result.notes:
                warn(note)
            report("features", i, len(jobs))
        seconds["features"] = time.perf_counter() - start
        features = _feature_frame(plan, blocks)

        start = time.perf_counter()
        previous = load_finished(runs_dir, warn)
        planned = list(plan_tasks(plan, features, set(previous)))
        todo = [task for _, task in planned if task is not None]
        finished = {key: previous[key] for key, task in planned if task is None}
        factors = {**read_factors(cache_dir), **learn_factors(previous.values())}
        report("runs", len(finished), len(planned))
        computed: list[RunResult] = []
        order = longest_first(todo, factors) if spread else todo
        for result in executor.map_unordered(run_classifier, order):
            if result.status == "ok":
                store_finished(runs_dir, result)
            finished[result.key] = result
            computed.append(result)
            task_seconds["classify"] += result.fit_seconds
            report("runs", len(finished), len(planned))
        seconds["classify"] = time.perf_counter() - start
        write_factors(cache_dir, learn_factors(computed))
    return BenchmarkResult(
        plan,
        [finished[key] for key, _ in planned],
        features,
        features_computed=sum(b.source == "computed" for b in blocks),
        features_cached=sum(b.source == "cached" for b in blocks),
        runs_computed=len(todo),
        runs_resumed=len(planned) - len(todo),
        seconds=seconds,
        saturation=saturation_table(blocks, {s.name: s.full_scale_g for s in plan.sensors}),
        cache_dir=os.path.abspath(cache_dir),
        task_seconds=task_seconds,
    )
