"""Zero-motion noise validation (paper section 3.1, Table 2), as data.

The SDT side runs the sensor's chain on x_ref = 0 at the recording rate
(20 kHz by default) for exactly as many input samples as give
``n_windows * window_length`` output samples (M = floor((N-1) F_t / F_ref) + 1
solved for the smallest N), with the call's seed and acquisition id 0. The
output is cut into ``n_windows`` non-overlapping windows from its first sample;
no settling time is dropped: on x_ref = 0 the only transient is the digital
filter's response to the first noise samples, far below the noise itself.

Per window: RMS of the mean-removed window, in mg (the physical sensor has a
zero-g offset that is not noise; on the SDT the mean is ~0 and both definitions
agree to < 0.01 mg), and NSD = sqrt(mean Welch PSD over 10..1500 Hz, cut to
the band the sensor's chain passes, :func:`sdt_framework.chain.passband`) in
ug/sqrt(Hz) (``scipy.signal.welch`` with ``nperseg=window_length``, Hann,
constant detrend, one-sided density). Each statistic is reported as mean, SD
(ddof=1) and a 95 % t-interval of the mean. Above the chain's bandwidth the
output is the filter's skirt, not the part's noise: a LIS3DH in high-resolution
mode (149 Hz digital low-pass) read 100.9 ug/sqrt(Hz) over 10..1500 Hz against
its configured 220; over 10..149 Hz it reads the part. ``band_hz`` is the band
used and ``band_note`` says when it was cut (the paper's ADXL345 keeps 10..1500 Hz:
its chain passes 1599 Hz).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import signal, stats

from ..chain import compile_chain, degrade, passband
from ..chain.checks import ChainInputError, check_signal
from ..specs import SensorSpec
from ..stages import uses_node

__all__ = [
    "NoiseCheck",
    "WindowStats",
    "noise_check",
    "window_stats",
    "zero_motion_cost",
    "zero_motion_length",
]

BAND_HZ = (10.0, 1500.0)
#: peak bytes per input and per output sample of :func:`noise_check`; measured with
#: ``tracemalloc`` at 64 and 512 windows of 2048: 4.0 (ADXL345), 4.2 (ADXL357) and
#: 7.5 (reference, output = input) x 8 bytes per input sample; this bound is above all three
BYTES_PER_INPUT_SAMPLE = 8 * 5
BYTES_PER_OUTPUT_SAMPLE = 8 * 4
#: input samples per second of the chain on x_ref = 0 (measured 21-40 M/s; rounded down)
INPUT_SAMPLES_PER_S = 15e6


def _summary(values: NDArray[np.float64]) -> dict[str, Any]:
    n = len(values)
    mean = float(np.mean(values))
    sd = float(np.std(values, ddof=1)) if n > 1 else 0.0
    half = float(stats.t.ppf(0.975, n - 1) * sd / math.sqrt(n)) if n > 1 else 0.0
    return {"mean": mean, "sd": sd, "ci95": [mean - half, mean + half]}


@dataclass(frozen=True)
class WindowStats:
    """Per-window noise RMS (mg) and NSD (ug/sqrt(Hz)) of one signal."""

    rms_mg: NDArray[np.float64]
    nsd_ug_rthz: NDArray[np.float64]

    def as_dict(self) -> dict[str, Any]:
        """``rms_mg`` / ``nsd_ug_rthz`` as the mean, with ``_sd``, ``_ci95``, ``_windows``."""
        out: dict[str, Any] = {}
        for key, values in (("rms_mg", self.rms_mg), ("nsd_ug_rthz", self.nsd_ug_rthz)):
            summary = _summary(values)
            out[key] = summary["mean"]
            out[f"{key}_sd"] = summary["sd"]
            out[f"{key}_ci95"] = summary["ci95"]
            out[f"{key}_windows"] = [float(v) for v in values]
        return out


def window_stats(
    x: NDArray[np.float64],
    fs: float,
    n_windows: int = 8,
    window_length: int = 2048,
    band_hz: tuple[float, float] = BAND_HZ,
) -> WindowStats:
    """Noise RMS and NSD (over ``band_hz``) of the first ``n_windows`` windows of ``x`` (g)."""
    windows = np.asarray(x[: n_windows * window_length], dtype=np.float64).reshape(
        n_windows, window_length
    )
    centred = windows - windows.mean(axis=1, keepdims=True)
    rms_mg = np.sqrt(np.mean(centred**2, axis=1)) * 1e3
    freqs, psd = signal.welch(windows, fs=fs, nperseg=window_length, axis=-1)
    band = (freqs >= band_hz[0]) & (freqs <= band_hz[1])
    nsd = np.sqrt(psd[:, band].mean(axis=1)) * 1e6
    return WindowStats(rms_mg=rms_mg, nsd_ug_rthz=nsd)


def zero_motion_length(sensor: SensorSpec, fs_ref: float, samples_out: int) -> int:
    """Smallest input length N at ``fs_ref`` whose chain output has ``samples_out`` samples."""
    ratio = Fraction(fs_ref) / Fraction(float(sensor.at_rate(fs_ref).sampling_rate_hz))
    return math.ceil((samples_out - 1) * ratio) + 1


def _check_request(
    sensor: SensorSpec, fs_ref: float, n_windows: int, window_length: int, label: str
) -> None:
    if n_windows < 2 or window_length < 16:
        raise ChainInputError(
            sensor.name,
            label,
            f"need >= 2 windows of >= 16 samples, got {n_windows} x {window_length}",
        )
    if not (math.isfinite(fs_ref) and fs_ref > 0):
        raise ChainInputError(sensor.name, label, f"reference rate must be > 0 Hz, got {fs_ref}")


def zero_motion_cost(
    sensor: SensorSpec, fs_ref: float, n_windows: int, window_length: int
) -> tuple[int, int, float]:
    """(input samples, peak bytes, seconds) of :func:`noise_check`, known before running it.

    Lets a caller refuse a size that cannot fit in memory, or ask before a long
    one, without allocating anything.
    """
    _check_request(sensor, fs_ref, n_windows, window_length, "")
    n_out = int(n_windows) * int(window_length)
    n_in = zero_motion_length(sensor, fs_ref, n_out)
    peak = BYTES_PER_INPUT_SAMPLE * n_in + BYTES_PER_OUTPUT_SAMPLE * n_out
    return n_in, peak, n_in / INPUT_SAMPLES_PER_S


@dataclass(frozen=True)
class NoiseCheck:
    """Result of a zero-motion check: both signals (in g), their rates and statistics."""

    sensor: str
    seed: int
    n_windows: int
    window_length: int
    fs_ref: float
    input_samples: int
    sdt_signal: NDArray[np.float64]
    sdt_fs: float
    sdt: WindowStats
    recording_signal: NDArray[np.float64] | None = None
    recording_fs: float | None = None
    recording: WindowStats | None = None
    band_hz: tuple[float, float] = BAND_HZ
    band_note: str = ""

    def comparison(self) -> dict[str, dict[str, float]]:
        """Relative error % (|SDT - rec| / rec, as paper Table 2) and Welch t-test p-values."""
        if self.recording is None:
            return {}
        errors: dict[str, float] = {}
        pvalues: dict[str, float] = {}
        for key, short in (("rms_mg", "rms"), ("nsd_ug_rthz", "nsd")):
            sdt_v, rec_v = getattr(self.sdt, key), getattr(self.recording, key)
            errors[short] = float(abs(sdt_v.mean() - rec_v.mean()) / rec_v.mean() * 100)
            pvalues[short] = float(stats.ttest_ind(sdt_v, rec_v, equal_var=False).pvalue)
        return {"relative_error_pct": errors, "p_value": pvalues}

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: ``sdt.rms_mg`` is the mean, ``sdt.rms_mg_sd`` / ``_ci95`` beside it."""
        out: dict[str, Any] = {
            "sensor": self.sensor,
            "seed": self.seed,
            "n_windows": self.n_windows,
            "window_length": self.window_length,
            "band_hz": list(self.band_hz),
            "band_note": self.band_note,
            "fs_ref_hz": self.fs_ref,
            "input_samples": self.input_samples,
            "sdt": {"fs_hz": self.sdt_fs, **self.sdt.as_dict()},
        }
        if self.recording is not None:
            out["recording"] = {"fs_hz": self.recording_fs, **self.recording.as_dict()}
            out.update(self.comparison())
        return out


def noise_check(
    sensor: SensorSpec,
    *,
    recording: ArrayLike | None = None,
    recording_fs: float | None = None,
    seed: int = 0,
    fs_ref: float = 20000.0,
    n_windows: int = 8,
    window_length: int = 2048,
    label: str = "",
) -> NoiseCheck:
    """Run the zero-motion check of ``sensor``, against a ``recording`` (in g) if given.

    ``recording_fs`` defaults to the sensor's output rate. A recording shorter
    than ``n_windows * window_length`` samples is an error.
    """
    _check_request(sensor, fs_ref, n_windows, window_length, label)
    if recording_fs is not None and not (math.isfinite(recording_fs) and recording_fs > 0):
        raise ChainInputError(
            sensor.name, label, f"recording rate must be > 0 Hz, got {recording_fs}"
        )
    needed = n_windows * window_length
    rec = None
    if recording is not None:  # checked before the chain runs: a bad recording costs nothing
        rec = check_signal(recording, sensor, label)
        if rec.ndim == 2 and 1 in rec.shape:
            rec = rec.ravel()
        if rec.ndim != 1 or rec.size < needed:
            raise ChainInputError(
                sensor.name,
                label,
                f"need one axis of >= {needed} samples ({n_windows} windows of {window_length}), "
                f"got shape {rec.shape}",
            )
    n_in = zero_motion_length(sensor, fs_ref, needed)
    zeros = np.zeros(n_in)
    # zero motion on every axis: a node stage (cross-axis) reads the other two as zeros too
    node = {"y": zeros, "z": zeros} if uses_node(compile_chain(sensor, fs_ref).sensor) else None
    out, fs_out = degrade(zeros, fs_ref, sensor, seed, label="x_ref = 0", other_axes=node)
    limit = passband(sensor, fs_ref)
    band = limit.clip(BAND_HZ)
    if band is None:
        raise ChainInputError(
            sensor.name, label, f"the NSD band {limit.note(BAND_HZ)}: no band left to read"
        )
    result = NoiseCheck(
        sensor.name,
        int(seed),
        n_windows,
        window_length,
        float(fs_ref),
        n_in,
        out,
        fs_out,
        window_stats(out, fs_out, n_windows, window_length, band),
        band_hz=band,
        band_note=limit.note(BAND_HZ),
    )
    if rec is None:
        return result
    rec_fs = float(recording_fs) if recording_fs is not None else fs_out
    return NoiseCheck(
        **{
            **result.__dict__,
            "recording_signal": rec,
            "recording_fs": rec_fs,
            "recording": window_stats(rec, rec_fs, n_windows, window_length, band),
        },
    )
