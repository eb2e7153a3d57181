"""Signals for the signal figures: one recording through every sensor, and zero-motion noise.

Fig. 2 needs a recording of the benchmark's own dataset, re-opened from the
configuration exactly as ``sdt benchmark`` opened it (which one: :mod:`.pick`),
degraded by each sensor.
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
from ..data.open import load_dataset, open_dataset
from ..data.recording import Dataset, Recording
from ..specs import SensorSpec
from ..validation import NoiseCheck, noise_check

__all__ = [
    "BandNoise",
    "SensorTrace",
    "config_dataset",
    "degrade_all",
    "noise_checks",
    "open_config_dataset",
]


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


def config_dataset(config: BenchmarkConfig, registry: Any) -> Dataset:
    """The benchmark's dataset, opened again (metadata only) with the same options."""
    options = dict(config.dataset_options)
    if config.dataset:
        return load_dataset(registry, registry.dataset(config.dataset), config.data, **options)
    return open_dataset(registry, config.data or "synthetic-pump", **options)


def open_config_dataset(
    config: BenchmarkConfig, registry: Any, dataset: Dataset | None = None
) -> list[Recording]:
    """The recordings the benchmark used (same dataset, options, machines, channels)."""
    dataset = dataset if dataset is not None else config_dataset(config, registry)
    recordings = dataset.recordings()
    if config.machines:
        recordings = [r for r in recordings if r.machine in config.machines]
    if config.channels:
        recordings = [r for r in recordings if r.channel in config.channels]
    return recordings


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


@dataclass(frozen=True)
class BandNoise:
    """A zero-motion check (its NSD read over the band the chain passes, ``check.band_hz``)
    and the profile's noise density (µg/√Hz) to read it against."""

    check: NoiseCheck
    configured: float

    def caption(self) -> str:
        """``sensor: RMS .. mg, NSD .. µg/√Hz over lo-hi Hz (configured ..; note)``."""
        check = self.check
        band = f"{check.band_hz[0]:g}-{check.band_hz[1]:.0f} Hz"
        extra = "; ".join(t for t in (f"configured {self.configured:g}", check.band_note) if t)
        return (
            f"{check.sensor}: RMS {check.sdt.rms_mg.mean():.2f} mg, "
            f"NSD {check.sdt.nsd_ug_rthz.mean():.1f} µg/√Hz over {band} ({extra})"
        )


def noise_checks(sensors: list[SensorSpec], seed: int = 0) -> list[BandNoise]:
    """Zero-motion checks (8 windows of 2048 samples) of every sensor that injects noise.

    Each NSD is the mean density over 10-1500 Hz cut to what that sensor's
    chain passes: above its bandwidth the output is the filter's skirt (or the
    quantiser's floor), not the part's noise.
    """
    return [
        BandNoise(noise_check(spec, seed=seed), float(spec.noise_density_ug_rthz))
        for spec in sensors
        if spec.inject_noise
    ]
