"""What is not the twin's fault, estimated first: clock, time offset, sign, axis alignment.

- **Clock.** The twin runs at the device's *measured* output rate, and its
  on-chip digital low-pass, which runs off the same clock, moves with it
  (``f_dig x measured / nominal``): an ADXL345 set to 3200 Hz that delivers
  3134 Hz is compared at 3134 Hz.
- **Offset.** The twin (sampled from the reference's start) is put on the
  device's time grid; the lag of the cross-correlation peak of the axis with
  the most motion, refined by a parabola through the peak and its neighbours,
  is the device's delay (sub-sample). It is searched within half a period of
  the device's strongest frequency (at most 0.2 s): a tone's lag is known only
  modulo its period, and the channels of one recorder share its clock.
- **Sign and alignment.** Least squares ``device_i ~ sum_j M_ij twin_j`` over
  the overlapping samples (mean removed), with only the twin axes that carry
  motion as regressors (standard deviation at least a tenth of the largest):
  a shaker drives one axis, and an axis at its noise floor determines
  nothing. A quiet axis keeps its unit column, and its share is taken out of
  the device before the fit: the twin's quiet axis still carries some of the
  shaker's tone (the reference's own cross-axis motion), and regressing the
  device on the active axes alone would count that share twice. ``R``,
  the orthogonal matrix whose active columns are nearest M's (the polar
  factor ``U V^T`` of their SVD; quiet axes completed from their unit
  vectors by Gram-Schmidt), holds the axis signs and the mounting's
  rotation and is applied to the twin; the gains stay out of it: they are
  the twin's to answer for and so stay in the comparison. With one axis, R
  is the sign. An axis also counts as carrying motion only if some device
  axis correlates with it by at least :data:`MIN_CORRELATION`: at rest the
  twin's axes carry only noise, and a rotation fitted to noise is noise. A
  pair with no such axis determines no rotation: the axes are kept as
  mounted, and the alignment says so.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage, signal

from ..chain import degrade
from ..errors import SDTError, shown
from ..specs import SensorSpec
from .pair import Pair

__all__ = ["ACTIVE_SHARE", "MIN_CORRELATION", "Alignment", "align", "at_rate", "require_rate"]

#: a twin axis whose spread is at least this share of the largest one determines its column
ACTIVE_SHARE = 0.1
#: below this correlation of device and twin on the main axis, no rotation is estimated
MIN_CORRELATION = 0.5


@dataclass(frozen=True)
class Alignment:
    """The estimated clock, offset and rotation, and both signals on one grid."""

    rate_hz: float  # device's measured output rate
    nominal_rate_hz: float
    delay_s: float  # device(t) ~ twin(t - delay)
    rotation: np.ndarray  # (n_axes, n_axes), applied to the twin
    twin: np.ndarray  # aligned twin on the device grid over the overlap
    device: np.ndarray  # device samples over the overlap
    reference: np.ndarray  # reference samples over the overlap (its own rate)
    correlation: float = 1.0  # best of the main twin axis with any device axis
    rotation_estimated: bool = True  # False: no axis carried shared motion, axes as mounted

    @property
    def signs(self) -> list[int]:
        """The sign of each axis in the rotation (its diagonal)."""
        return [int(np.sign(v)) or 1 for v in np.diag(self.rotation)]

    @property
    def angles_deg(self) -> list[float]:
        """Angle between each twin axis and the device axis it maps to, degrees."""
        diagonal = np.clip(np.abs(np.diag(self.rotation)), 0.0, 1.0)
        return [float(np.degrees(np.arccos(v))) for v in diagonal]


def require_rate(sensor: SensorSpec) -> None:
    """Refuse a sensor without an output rate of its own (``native-reference``: a reference
    chain samples at the recording's rate, so there is no device clock to compare)."""
    if not isinstance(sensor.sampling_rate_hz, float):
        raise SDTError(
            f"--sensor {sensor.name}: samples at the recording's own rate "
            f"({shown(sensor.sampling_rate_hz)}), so it has no twin of a device to check or fit; "
            f"give the profile of the device's part (e.g. adxl345)"
        )


def at_rate(sensor: SensorSpec, rate_hz: float) -> SensorSpec:
    """``sensor`` run at ``rate_hz``: its digital corner scaled with the clock."""
    nominal = sensor.sampling_rate_hz
    if not isinstance(nominal, float):
        return sensor
    update: dict[str, float] = {"sampling_rate_hz": rate_hz}
    if sensor.digital_cutoff_hz is not None:
        update["digital_cutoff_hz"] = sensor.digital_cutoff_hz * rate_hz / nominal
    return sensor.model_copy(update=update)


def _lag(a: np.ndarray, b: np.ndarray, limit: int) -> float:
    """Sub-sample lag of ``b`` behind ``a`` (peak of their cross-correlation)."""
    corr = signal.correlate(b - b.mean(), a - a.mean(), mode="full", method="fft")
    lags = signal.correlation_lags(len(b), len(a), mode="full")
    window = np.abs(lags) <= limit
    corr, lags = corr[window], lags[window]
    peak = int(np.argmax(np.abs(corr)))
    if 0 < peak < len(corr) - 1:
        y0, y1, y2 = np.abs(corr[peak - 1 : peak + 2])
        denom = y0 - 2 * y1 + y2
        return float(lags[peak] + (0.5 * (y0 - y2) / denom if denom else 0.0))
    return float(lags[peak])


def _resample_at(x: np.ndarray, first: float, n: int) -> np.ndarray:
    """Rows of ``x`` at sample positions ``first, first + 1, ...`` (``n`` of them).

    Quintic B-spline interpolation (scipy.ndimage.shift, order 5): flat to well
    above a fifth of the rate, where linear interpolation would lose 0.2 dB for
    a third of a sample, and local (a Fourier phase ramp would smear the jump
    between a long signal's two ends over every sample).
    """
    whole = int(np.floor(first))
    moved = ndimage.shift(x, (0, -(first - whole)), order=5, mode="nearest")
    return moved[:, whole : whole + n]


def _rotation(columns: np.ndarray, active: np.ndarray, n: int) -> np.ndarray:
    """The orthogonal matrix whose ``active`` columns are nearest ``columns`` (polar factor),
    the others completed from their unit vectors (Gram-Schmidt)."""
    u, _, vt = np.linalg.svd(columns, full_matrices=False)
    rotation = np.zeros((n, n))
    rotation[:, active] = u @ vt
    basis = list((u @ vt).T)
    for j in (j for j in range(n) if j not in set(active.tolist())):
        v = np.eye(n)[j] - sum(float(b[j]) * b for b in basis)
        rotation[:, j] = v / np.linalg.norm(v)
        basis.append(rotation[:, j])
    return rotation


def align(pair: Pair, sensor: SensorSpec, seed: int = 0) -> Alignment:
    """Run the reference through ``sensor``'s twin at the device's rate and align it."""
    require_rate(sensor)
    ref, dev = pair.reference, pair.device
    clocked = at_rate(sensor, dev.rate_hz)
    rows = [
        degrade(
            row,
            ref.rate_hz,
            clocked.for_axis(axis),
            seed=seed,
            first_index=i,
            label=f"{pair.name} {ref.label} {axis}",
        )
        for i, (axis, row) in enumerate(zip(ref.axes, ref.values, strict=True))
    ]  # each axis with its own figures (per_axis), its own noise draw
    twin, fs = np.stack([row for row, _ in rows]), rows[0][1]
    twin_t = ref.start_s + np.arange(twin.shape[1]) / fs
    start = max(ref.start_s, dev.start_s) + 0.25  # a margin for the offset and filter starts
    end = min(twin_t[-1], dev.end_s) - 0.25 - 2 / dev.rate_hz  # room for the shift
    dev_t = dev.start_s + np.arange(dev.values.shape[1]) / dev.rate_hz
    keep = (dev_t >= start) & (dev_t <= end)
    grid = dev_t[keep]
    device = dev.values[:, keep]
    coarse = np.stack([np.interp(grid, twin_t, row) for row in twin])
    main = int(np.argmax(device.std(axis=1)))
    f, density = signal.periodogram(device[main], fs=dev.rate_hz, detrend="constant")
    dominant = float(f[1:][np.argmax(density[1:])])
    search = min(0.2, 0.5 / dominant)  # a tone's lag is known only modulo its period
    delay = _lag(coarse[main], device[main], int(search * dev.rate_hz)) / dev.rate_hz
    shifted = _resample_at(twin, (grid[0] - delay - twin_t[0]) * fs, len(grid))
    centred_twin = shifted - shifted.mean(axis=1, keepdims=True)
    centred_dev = device - device.mean(axis=1, keepdims=True)
    spread = centred_twin.std(axis=1)
    n = len(spread)
    corr = np.abs(np.corrcoef(centred_twin, centred_dev)[:n, n:])  # twin j vs device i
    correlation = float(corr.max(axis=1)[main])
    active = np.flatnonzero(
        (spread >= ACTIVE_SHARE * spread.max()) & (corr.max(axis=1) >= MIN_CORRELATION)
    )  # axes that carry motion the device shares
    rotation = np.eye(n)
    if len(active):
        quiet = np.setdiff1d(np.arange(n), active)
        target = centred_dev - np.eye(n)[:, quiet] @ centred_twin[quiet]
        fitted, *_ = np.linalg.lstsq(centred_twin[active].T, target.T, rcond=None)
        rotation = _rotation(fitted.T, active, n)
    ref_t = ref.start_s + np.arange(ref.values.shape[1]) / ref.rate_hz
    reference = ref.values[:, (ref_t >= start - delay) & (ref_t <= end - delay)]
    return Alignment(dev.rate_hz, float(sensor.sampling_rate_hz), delay, rotation,
                     rotation @ shifted, device, reference, correlation,
                     bool(len(active)))  # fmt: skip
