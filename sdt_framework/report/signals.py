"""Signals for the signal figures: one recording through every sensor, and zero-motion noise.

Fig. 2 needs a recording of the benchmark's own dataset, re-opened from the
configuration exactly as ``sdt benchmark`` opened it, degraded by each sensor.
Fig. 4 needs the zero-motion chain output of each sensor that injects noise,
which :func:`sdt_framework.validation.noise_check` already computes.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..bench.config import BenchmarkConfig
from ..chain import degrade
from ..data.open import open_dataset
from ..data.recording import Recording
from ..errors import SDTError
from ..specs import SensorSpec
from ..validation import NoiseCheck, noise_check

__all__ = ["SensorTrace", "degrade_all", "noise_checks", "open_config_dataset", "pick_recording"]


@dataclass(frozen=True)
class SensorTrace:
    """One sensor's view of an acquisition: samples in g at ``fs`` Hz, and its full scale."""

    sensor: str
    signal: NDArray[np.float64]
    fs: float
    full_scale_g: float
    lsb_g: float

    @property
    def clipped(self) -> bool:
        """True when some sample sits at the full-scale limit (within one LSB)."""
        return bool(np.max(np.abs(self.signal)) >= self.full_scale_g - self.lsb_g)


def open_config_dataset(config: BenchmarkConfig, registry: Any) -> list[Recording]:
    """The recordings the benchmark used (same dataset, options, machines, channels)."""
    options = dict(config.dataset_options)
    if config.dataset:
        dataset = registry.dataset(config.dataset).loader(config.data, **options)
    else:
        dataset = open_dataset(registry, config.data or "synthetic-pump", **options)
    recordings = dataset.recordings()
    if config.machines:
        recordings = [r for r in recordings if r.machine in config.machines]
    if config.channels:
        recordings = [r for r in recordings if r.channel in config.channels]
    return recordings


def pick_recording(recordings: list[Recording]) -> Recording:
    """The recording for Fig. 2, as in the paper when possible.

    Preference: the highest severity of "cavitation suction" (the paper's
    Motor-4 cavitation suction 4), else of any condition containing
    "cavitation", else of any fault; on channel ch1 when present, else the
    first channel. Falls back to the first recording.
    """
    if not recordings:
        raise SDTError("the dataset has no recordings to draw")

    def best(pool: list[Recording]) -> Recording | None:
        if not pool:
            return None
        channel = "ch1" if any(r.channel == "ch1" for r in pool) else min(r.channel for r in pool)
        pool = [r for r in pool if r.channel == channel]
        return max(pool, key=lambda r: (r.severity or 0, r.machine, r.run))

    for test in (
        lambda r: r.condition == "cavitation suction",
        lambda r: "cavitation" in r.condition,
        lambda r: r.severity is not None,
    ):
        chosen = best([r for r in recordings if test(r)])
        if chosen is not None:
            return chosen
    return recordings[0]


def degrade_all(
    recording: Recording, sensors: list[SensorSpec], seed: int = 0
) -> tuple[NDArray[np.float64], list[SensorTrace]]:
    """The first acquisition of ``recording`` (in g) and what each sensor makes of it."""
    x = recording.load()[0]
    fs = recording.sampling_rate_hz
    traces = []
    for spec in sensors:
        y, fs_out = degrade(x, fs, spec, seed, label=recording.recording_id)
        # a chain without a range or converter (native-reference) neither clips nor quantises
        full_scale = spec.full_scale_g if spec.full_scale_g is not None else np.inf
        lsb = 2 * full_scale / 2**spec.adc_bits if spec.adc_bits is not None else 0.0
        traces.append(SensorTrace(spec.name, y, fs_out, full_scale, lsb))
    return x, traces


def noise_checks(sensors: list[SensorSpec], seed: int = 0) -> list[NoiseCheck]:
    """Zero-motion checks (8 windows of 2048 samples) of every sensor that injects noise."""
    return [noise_check(spec, seed=seed) for spec in sensors if spec.inject_noise]
