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
from ..data.open import open_dataset
from ..data.recording import Recording
from ..specs import SensorSpec
from ..validation import NoiseCheck, noise_check
from ..validation.noise_check import BAND_HZ, WindowStats, window_stats
from .passband import passband

__all__ = [
    "BandNoise",
    "SensorTrace",
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
    """A zero-motion check with its NSD read over the band the sensor's chain passes.

    ``band_hz`` is the check's 10-1500 Hz band cut to the chain's bandwidth
    (:func:`~.passband.passband`), ``note`` says so when it was cut, and
    ``configured`` is the profile's noise density (µg/√Hz) to read it against.
    """

    check: NoiseCheck
    band_hz: tuple[float, float]
    stats: WindowStats
    note: str
    configured: float

    def caption(self) -> str:
        """``sensor: RMS .. mg, NSD .. µg/√Hz over lo-hi Hz (configured ..; note)``."""
        band = f"{self.band_hz[0]:g}-{self.band_hz[1]:.0f} Hz"
        extra = "; ".join(t for t in (f"configured {self.configured:g}", self.note) if t)
        return (
            f"{self.check.sensor}: RMS {self.stats.rms_mg.mean():.2f} mg, "
            f"NSD {self.stats.nsd_ug_rthz.mean():.1f} µg/√Hz over {band} ({extra})"
        )


def noise_checks(sensors: list[SensorSpec], seed: int = 0) -> list[BandNoise]:
    """Zero-motion checks (8 windows of 2048 samples) of every sensor that injects noise.

    Each NSD is the mean density over 10-1500 Hz cut to what that sensor's
    chain passes: above its bandwidth the output is the filter's skirt (or the
    quantiser's floor), not the part's noise.
    """
    out = []
    for spec in sensors:
        if not spec.inject_noise:
            continue
        check = noise_check(spec, seed=seed)
        limit = passband(spec, check.fs_ref)
        band = limit.clip(BAND_HZ) or BAND_HZ
        stats = window_stats(
            check.sdt_signal, check.sdt_fs, check.n_windows, check.window_length, band
        )
        configured = float(spec.noise_density_ug_rthz)
        out.append(BandNoise(check, band, stats, limit.note(BAND_HZ), configured))
    return out
