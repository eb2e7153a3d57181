"""Stage 1 of a benchmark: recording -> SDT chain -> windows -> features, cached.

One task per recording: its samples are read once, then degraded by every
sensor (with the figures of the axis its channel is mounted on) for every
repetition and featurised. Repetition ``r`` draws the SDT
noise from ``derive_seed(seed, "noise", r, recording_id)``, so results do not
depend on the order or the process a task runs in. A profile that injects no
noise (the reference) is deterministic: it is computed once and shared by all
repetitions. The stages at the recording's rate (mechanical and analog
filters) run once per distinct setting (``chain.shared``) and are shared by
the repetitions and by sensors that differ only in later stages, bit for bit.

Feature blocks are cached on disk keyed by the dataset, the recording (and
the digest of its file's bytes, :mod:`sdt_framework.data.digest`), the
sensor's and the feature set's content hashes, the windowing and the noise
seed, so adding a classifier to a finished benchmark recomputes no features,
and a file rewritten with other samples is never served from the cache, even
with its size and modification time kept. A failure is never cached. A
corrupt entry (truncated, not an archive, wrong arrays) or one whose contents
no longer match their checksum (:mod:`.feature_cache`) is discarded and
recomputed, and named in a note the orchestrator shows as a warning (workers
cannot print reliably: on Dask their output goes to the worker's log). A feature
set in orders of the running speed is handed the recording's context (speed,
machine, channel: :mod:`.feature_context`), which enters the cache key.
"""

from __future__ import annotations

import hashlib
import json
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..chain import compile_chain
from ..chain.shared import SharedPrefix, prefix_key
from ..data.cache import CORRUPT_ENTRY_ERRORS
from ..data.recording import Recording
from ..features import extract
from ..seeding import derive_seed
from ..specs import FeatureContext, FeatureSetSpec, SensorSpec
from ..stages import StageSpec, draw_unit, has_tolerances, is_random, uses_node
from .feature_cache import (
    CachedBlock,
    ChecksumMismatchError,
    read_entry,
    source_states,
    write_entry,
)
from .job_input import open_noting

__all__ = ["FeatureBlock", "FeatureJob", "RecordingFeatures", "featurise_recording", "noise_seed"]

CACHE_VERSION = "3"  # 2: full-scale counts and a checksum; 3: files known by their digest


@dataclass(frozen=True)
class FeatureBlock:
    """Features of one recording as seen by one sensor in one repetition."""

    recording_id: str
    sensor: str
    repeat: int
    values: np.ndarray  # float32 (n_windows, n_features)
    acquisition: np.ndarray
    window: np.ndarray
    source: str  # computed | cached (read from disk) | shared (deterministic chain)
    unit: int = -1  # physical unit drawn from the tolerances; -1: the nominal profile
    at_full_scale: int = 0  # samples of the degraded signal at +-full scale (saturated)
    samples: int = 0  # samples of the degraded signal


@dataclass
class RecordingFeatures:
    """What featurising one recording produced: its blocks, and notes for the user."""

    blocks: list[FeatureBlock] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    seconds: float = 0.0  # time the worker spent on the recording (for bench_scale's ideal)


@dataclass(frozen=True)
class FeatureJob:
    """Everything a worker needs to featurise one recording (picklable)."""

    recording: Recording
    dataset_key: str
    sensors: tuple[SensorSpec, ...]
    feature_set: FeatureSetSpec
    repeats: int
    seed: int
    window_s: float
    settle_s: float
    cache_dir: str | None
    axis: str = "x"  # the sensor axis this recording's channel is mounted on
    units: int | None = None  # physical units per sensor (None: the nominal profile only)
    node: tuple[Recording, ...] = ()  # the triaxial node's other two axes (for cross-axis)
    #: the specs of the stages the sensors' tolerances name, which a drawn unit adds and binds
    #: here: a worker process has no registry of its own
    stages: tuple[StageSpec, ...] = ()
    #: a feature set in orders of the running speed: the recording's speed, machine, channel
    context: FeatureContext | None = None


def noise_seed(sensor: SensorSpec, seed: int, repeat: int, recording_id: str) -> int | None:
    """The chain seed of one repetition, or None for a chain without randomness."""
    if not is_random(sensor):
        return None
    return derive_seed(seed, "noise", repeat, recording_id)


def _key(
    job: FeatureJob, sensor: SensorSpec, chain_seed: int | None, states: dict[str, str | None]
) -> str:
    parts = {
        "version": CACHE_VERSION,
        "dataset": job.dataset_key,
        "recording": job.recording.metadata(),
        "source_state": states[job.recording.source],
        "sensor": sensor.content_hash(),
        "features": job.feature_set.content_hash(),
        "window_s": job.window_s,
        "settle_s": job.settle_s,
        "seed": chain_seed,
    }
    if _needs_node(sensor, job):  # the other axes' samples enter the output
        parts["node"] = [[r.metadata(), states[r.source]] for r in job.node]
    if job.context is not None and job.feature_set.needs_speed:  # speed and bearings enter
        parts["context"] = job.context.content()
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()


def _needs_node(sensor: SensorSpec, job: FeatureJob) -> bool:
    """Whether ``sensor``'s chain (bound, as compiled) reads the node's other axes."""
    return uses_node(compile_chain(sensor, job.recording.sampling_rate_hz).sensor)


def _cache_path(job: FeatureJob, key: str) -> Path | None:
    if job.cache_dir is None:
        return None
    return Path(job.cache_dir) / "features" / key[:2] / f"{key}.npz"


def _compute(
    shared: SharedPrefix, job: FeatureJob, sensor: SensorSpec, chain_seed: int | None
) -> CachedBlock:
    degraded, fs_out = shared.degrade(sensor, seed=chain_seed or 0, noise=chain_seed is not None)
    own = "the file's rate (its header's, or the manifest's sampling_rate_hz)"
    where = own if fs_out == shared.fs else f"{sensor.name}'s output rate"  # for a band error
    table = extract(degraded, fs_out, job.feature_set, window_s=job.window_s,
                    settle_s=job.settle_s, label=shared.label, rate_from=where,
                    context=job.context)  # fmt: skip
    at_full_scale = 0
    if sensor.requantise and sensor.full_scale_g is not None:  # clipped samples sit there
        at_full_scale = int(np.count_nonzero(np.abs(degraded) >= sensor.full_scale_g))
    counts = np.array([at_full_scale, degraded.size], dtype=np.int64)
    return table.values, table.acquisition, table.window, counts


def _variants(job: FeatureJob) -> list[tuple[SensorSpec, int]]:
    """(sensor as run, unit) pairs: the nominal profile, or each drawn unit of it.

    With ``job.units`` set, unit k of each sensor is drawn from its tolerances
    (:func:`sdt_framework.stages.draw_unit`, seeded by the base seed, the
    sensor's base name and k); a sensor without tolerances has identical
    units: only unit 0 is run and the others repeat its blocks.
    """
    if job.units is None:
        return [(named.for_axis(job.axis), -1) for named in job.sensors]
    table = {spec.name: spec for spec in job.stages}
    return [
        (draw_unit(named, job.seed, unit, table).for_axis(job.axis), unit)
        for named in job.sensors
        for unit in range(job.units)
        if unit == 0 or has_tolerances(named)
    ]


def _by_prefix(job: FeatureJob) -> list[list[tuple[SensorSpec, int]]]:
    """The job's sensors (with their axis's figures), in groups of equal recording-rate prefix.

    Sensors whose mechanical and analog stages are equal (sweep points that
    differ in later stages) then share one prefix run, and, taken repetition
    by repetition, their sampled signals and noise draws (``chain.shared``).
    """
    fs = job.recording.sampling_rate_hz
    groups: dict[str, list[tuple[SensorSpec, int]]] = {}
    for sensor, unit in _variants(job):  # the name stays
        groups.setdefault(prefix_key(sensor, fs), []).append((sensor, unit))
    return list(groups.values())


def featurise_recording(job: FeatureJob) -> RecordingFeatures:
    """Features of one recording for every (sensor, unit, repetition) of the job."""
    start = time.perf_counter()
    shared: SharedPrefix | None = None  # the recording, read on first need
    out = RecordingFeatures()
    blocks = out.blocks
    n_features = len(job.feature_set.feature_names)
    done: dict[tuple[str, int, int | None], FeatureBlock] = {}
    states = source_states((job.recording, *job.node), job.cache_dir)  # for the cache keys
    for group, repeat in ((g, r) for g in _by_prefix(job) for r in range(job.repeats)):
        for sensor, unit in group:
            chain_seed = noise_seed(sensor, job.seed, repeat, job.recording.recording_id)
            if (sensor.name, unit, chain_seed) in done:  # deterministic: same every repetition
                blocks.append(
                    _relabel(done[(sensor.name, unit, chain_seed)], repeat, unit, "shared")
                )
                continue
            key = "" if job.cache_dir is None else _key(job, sensor, chain_seed, states)
            path = _cache_path(job, key)
            arrays = None
            if path is not None and path.exists():
                try:
                    arrays = read_entry(path, key, n_features)
                    source = "cached"
                except ChecksumMismatchError:
                    out.notes.append(
                        f"feature-cache entry {path} was changed after it was written (its "
                        f"checksum does not match); discarded, recomputing it"
                    )
                    path.unlink(missing_ok=True)
                except CORRUPT_ENTRY_ERRORS as exc:
                    out.notes.append(
                        f"corrupt feature-cache entry {path} ({type(exc).__name__}) "
                        f"discarded; recomputing it"
                    )
                    path.unlink(missing_ok=True)
            if arrays is None:
                if shared is None:
                    shared = open_noting(job.recording, job.node, job.axis, out.notes)
                arrays = _compute(shared, job, sensor, chain_seed)
                source = "computed"
                if path is not None:
                    write_entry(path, key, arrays)
            values, acquisition, window, counts = arrays
            block = FeatureBlock(
                job.recording.recording_id,
                sensor.name,
                repeat,
                values,
                acquisition,
                window,
                source,
                unit,
                int(counts[0]),
                int(counts[1]),
            )
            done[(sensor.name, unit, chain_seed)] = block
            blocks.append(block)
    if job.units is not None:  # units of a sensor without tolerances: unit 0's blocks
        same = {n.name for n in job.sensors if not has_tolerances(n)}
        firsts = [b for b in blocks if b.unit == 0 and b.sensor in same]
        blocks += [_relabel(b, b.repeat, u, "shared") for u in range(1, job.units) for b in firsts]
    out.seconds = time.perf_counter() - start
    return out


def _relabel(block: FeatureBlock, repeat: int, unit: int, source: str) -> FeatureBlock:
    return FeatureBlock(
        block.recording_id,
        block.sensor,
        repeat,
        block.values,
        block.acquisition,
        block.window,
        source,
        unit,
        block.at_full_scale,
        block.samples,
    )
