"""Allan deviation of zero-motion noise, and the noise terms read off the curve.

The curve is the overlapping Allan deviation (``allantools.oadev``, the signal
in g as ``data_type="freq"`` at its rate) at about 10 log-spaced cluster
lengths m per decade, from one sample up to a twentieth of the record: every
tau has at least 20 non-overlapping clusters, so the IEEE Std 952-1997
estimate error 1 / sqrt(2 (N/m - 1)) stays under 16 %.

Read-off (IEEE Std 952-1997 Annex C; the slope procedure of MathWorks'
"Inertial Sensor Noise Analysis Using Allan Variance" example):

- the local log-log slope at each tau is the least-squares slope over the
  taus within +-0.5 decade;
- white noise: the shortest-tau stretch whose slope is -1/2 (from the first
  tau within 0.05, while within 0.1); a line of slope -1/2 through it (mean of
  log sigma + log tau / 2, weighted by 1/tau) gives N = sigma(1 s), in
  g sqrt(s) = g/sqrt(Hz), extrapolated when 1 s is beyond the taus;
- bias instability: the flat region, where the slope is 0 +- 0.1 or changes
  sign (a minimum, a hump's top, a 1/f plateau), half a decade inside both
  ends of the taus; B = sigma there / sqrt(2 ln 2 / pi), the 1/f floor being
  0.664 B (:func:`read_floor`).

A curve without such a stretch gets NaN and the reason, never a guess.

Units: N relates to the one-sided density S0 (g^2/Hz) of white noise by
sigma^2(tau) = S0 / (2 tau) (NIST SP 1065, eq. 65-66 with S_y one-sided, as
``allantools.psd2allan``), so N = NSD / sqrt(2) for a datasheet NSD; the
velocity random walk is N in (m/s)/sqrt(h) = N [g sqrt(s)] x g0 x 60, since
sqrt(1 h) = 60 sqrt(s) (the inverse of the ``vrw`` stage's conversion).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..units import G_N

__all__ = [
    "FLOOR_FACTOR",
    "AllanCurve",
    "allan_curve",
    "allan_seconds",
    "allan_taus",
    "gauss_markov_adev",
    "local_slopes",
    "mean_oadev",
    "read_floor",
    "read_white",
    "white_values",
]

ROOT_HOUR = 60.0  # sqrt(3600 s), per sqrt(h) -> per sqrt(s)
FLOOR_FACTOR = math.sqrt(2.0 * math.log(2.0) / math.pi)  # 0.6643: 1/f floor = 0.664 B
PER_DECADE = 10
CLUSTERS = 20  # tau <= record / 20
HALF_WIDTH = 0.5  # decades each side of a tau for its local slope
SLOPE_TOL = 0.1
#: overlapping ADEV throughput, (samples x taus) per second: measured 183-187 M/s
#: (1 M and 4 M samples, 44 and 51 taus); peak memory 3 x 8 bytes per sample on top
#: of the signal, below the chain's own peak per sample, so the memory bound holds
SAMPLE_TAUS_PER_S = 100e6


def allan_taus(n: int, fs: float) -> NDArray[np.float64]:
    """Taus (s) for ``n`` samples at ``fs``: m = 1 .. n // 20, about 10 per decade."""
    top = max(1, n // CLUSTERS)
    count = round(math.log10(top) * PER_DECADE) + 1 if top > 1 else 1
    return np.unique(np.round(np.logspace(0.0, math.log10(top), count))).astype(float) / fs


def allan_seconds(n: int) -> float:
    """Estimated run time of one curve of ``n`` samples (for the command's size check)."""
    return n * len(allan_taus(n, 1.0)) / SAMPLE_TAUS_PER_S


def mean_oadev(
    y: ArrayLike, fs: float, taus: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Overlapping ADEV (``allantools.oadev``) of each row of ``y``, RMS-averaged over rows.

    Returns ``(taus_used, adev)``; rows are independent records of one process.
    """
    import allantools  # imported on use: only the Allan check needs it

    rows = np.atleast_2d(np.asarray(y, dtype=np.float64))
    curves = [allantools.oadev(r, rate=fs, data_type="freq", taus=taus)[:2] for r in rows]
    return curves[0][0], np.sqrt(np.mean([c[1] ** 2 for c in curves], axis=0))


def gauss_markov_adev(taus: ArrayLike, sigma: float, tc: float) -> NDArray[np.float64]:
    """Closed-form ADEV of a first-order Gauss-Markov process (SD ``sigma``, time ``tc``).

    sigma^2(t) = (4 V(t) - V(2t)) / (2 t^2), V(t) = 2 sigma^2 T^2 (t/T - 1 + exp(-t/T))
    the variance of its integral over t; the hump peaks at 0.618 sigma near t = 1.89 T.
    """
    t = np.asarray(taus, dtype=np.float64)

    def v(u: NDArray[np.float64]) -> NDArray[np.float64]:
        return 2 * sigma**2 * tc**2 * (u / tc + np.expm1(-u / tc))  # expm1: exact at u << T

    return np.sqrt((4 * v(t) - v(2 * t)) / (2 * t**2))


def local_slopes(taus: NDArray[np.float64], adev: NDArray[np.float64]) -> NDArray[np.float64]:
    """Log-log slope at each tau: least squares over the taus within +-0.5 decade.

    The neighbours on each side always count, so the sparse shortest taus get a slope too.
    """
    x, y = np.log10(taus), np.log10(adev)
    index = np.arange(len(x))
    w = (np.abs(x[:, None] - x[None, :]) <= HALF_WIDTH + 1e-9) | (
        np.abs(index[:, None] - index[None, :]) <= 1
    )
    n = w.sum(axis=1)
    dx = x[None, :] - ((w @ x) / n)[:, None]
    dy = y[None, :] - ((w @ y) / n)[:, None]
    return (w * dx * dy).sum(axis=1) / (w * dx * dx).sum(axis=1)


def _span(taus: NDArray[np.float64], slopes: NDArray[np.float64]) -> str:
    return (
        f"for tau {taus[0]:.3g}-{taus[-1]:.3g} s the slope runs from "
        f"{np.nanmin(slopes):+.2f} to {np.nanmax(slopes):+.2f}"
    )


def read_white(
    taus: NDArray[np.float64], adev: NDArray[np.float64], slopes: NDArray[np.float64]
) -> tuple[float, tuple[float, float] | None, str | None]:
    """N = sigma(1 s) on the -1/2 line through the first slope -1/2 stretch: (N, taus, reason).

    The stretch starts at the first tau whose slope is within 0.05 of -1/2 (where
    a band-limited chain's filters no longer lower the curve) and runs while the
    slope stays within 0.1. The line's level is the mean of log(sigma sqrt(tau))
    weighted by 1/tau, as the variance of each estimate grows with tau (IEEE 952).
    """
    near = np.abs(slopes + 0.5)
    if not (near <= SLOPE_TOL / 2).any():
        return math.nan, None, f"no slope -1/2 region: {_span(taus, slopes)}"
    first = int(np.argmax(near <= SLOPE_TOL / 2))
    on = near[first:] <= SLOPE_TOL
    stop = first + (int(np.argmin(on)) if not on.all() else len(on))
    t, d = taus[first:stop], adev[first:stop]
    n = float(np.exp(np.average(np.log(d) + 0.5 * np.log(t), weights=1.0 / t)))
    return n, (float(t[0]), float(t[-1])), None


def read_floor(
    taus: NDArray[np.float64], adev: NDArray[np.float64], slopes: NDArray[np.float64]
) -> tuple[float, float, str | None]:
    """The bias-instability floor and its tau: (sigma_floor, tau, reason); B = floor / 0.664.

    Flat points have a slope of 0 +- 0.1 or sit where the slope changes sign; in
    each contiguous run of them the point whose slope is nearest 0 is the run's
    stationary point (a minimum, a hump's top, or a 1/f plateau), and the lowest
    of those is the floor (the smoothed slopes locate it, the curve gives its
    value, so a noisy plateau is not read at its lowest estimate). Only taus half
    a decade inside both ends count (their slopes rest on points either side,
    not on the noisiest last ones alone), and a flat run at the shortest taus
    that a -1/2 stretch follows is the sensor's bandwidth (samples correlated by
    its filters), not a floor.
    """
    x = np.log10(taus)
    inner = (x >= x[0] + HALF_WIDTH) & (x <= x[-1] - HALF_WIDTH)  # a whole window each side
    flat = np.abs(slopes) <= SLOPE_TOL
    turns = np.flatnonzero(np.sign(slopes[:-1]) * np.sign(slopes[1:]) < 0)
    flat[turns] = flat[turns + 1] = True
    lead = int(np.argmin(flat)) if not flat.all() else len(flat)  # leading flat run
    where = ""
    if 0 < lead < len(flat) and (np.abs(slopes[lead:] + 0.5) <= SLOPE_TOL).any():
        inner[:lead] = False  # flat below the white-noise taus: the sensor's bandwidth
        where = f" beyond the sensor's bandwidth (flat up to {taus[lead - 1]:.3g} s)"
    if not inner.any():
        span = f"{taus[0]:.3g}-{taus[-1]:.3g} s"
        return math.nan, math.nan, f"no flat region can be read{where}: taus {span}, too few"
    flat &= inner
    if not flat.any():
        span = _span(taus[inner], slopes[inner])
        return math.nan, math.nan, f"no flat region (slope 0 +- {SLOPE_TOL}){where}: {span}"
    stretch = np.cumsum(np.diff(flat.astype(int), prepend=0) == 1)  # contiguous runs
    ranked = np.where(flat, np.abs(slopes), np.inf)
    best = [
        int(np.argmin(np.where(stretch == k, ranked, np.inf))) for k in np.unique(stretch[flat])
    ]
    i = min(best, key=lambda j: adev[j])  # each stretch's stationary point; the lowest
    return float(adev[i]), float(taus[i]), None


@dataclass(frozen=True)
class AllanCurve:
    """One signal's Allan deviation (g) and the values read off it (NaN + reason if absent)."""

    label: str
    fs: float
    samples: int
    taus: NDArray[np.float64]
    adev: NDArray[np.float64]
    n_g: float
    n_taus: tuple[float, float] | None
    n_reason: str | None
    floor_g: float
    floor_tau: float
    b_reason: str | None

    @property
    def b_g(self) -> float:
        """Bias instability B = floor / 0.664, g."""
        return self.floor_g / FLOOR_FACTOR

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready, in ug and s; NaN values are None beside their reason."""
        return {
            "fs_hz": self.fs,
            "samples": self.samples,
            "tau_range_s": [float(self.taus[0]), float(self.taus[-1])] if len(self.taus) else None,
            "tau_s": self.taus.tolist(),
            "adev_ug": (self.adev * 1e6).tolist(),
            **white_values(self.n_g),
            "white_fit_tau_s": list(self.n_taus) if self.n_taus else None,
            "white_reason": self.n_reason,
            "bias_instability_ug": _finite(self.b_g * 1e6),
            "floor_ug": _finite(self.floor_g * 1e6),
            "floor_tau_s": _finite(self.floor_tau),
            "bias_reason": self.b_reason,
        }


def _finite(value: float) -> float | None:
    """``value`` for JSON: None when it is NaN (not read off) or infinite."""
    return None if value is None or not math.isfinite(value) else float(value)


def white_values(n_g: float | None) -> dict[str, float | None]:
    """N as sigma(1 s) and as one-sided NSD in ug/sqrt(Hz), and as VRW in (m/s)/sqrt(h)."""
    n = math.nan if n_g is None else n_g
    return {
        "n_ug_rthz": _finite(n * 1e6),
        "nsd_ug_rthz": _finite(n * math.sqrt(2.0) * 1e6),
        "vrw_mps_rthr": _finite(n * G_N * ROOT_HOUR),
    }


def allan_curve(x: ArrayLike, fs: float, label: str = "") -> AllanCurve:
    """Overlapping ADEV of one record ``x`` (g) at ``fs`` and its read-off (module doc)."""
    x = np.asarray(x, dtype=np.float64).ravel()
    taus, adev = mean_oadev(x, fs, allan_taus(x.size, fs))
    keep = np.isfinite(adev) & (adev > 0)
    taus, adev = np.asarray(taus)[keep], np.asarray(adev)[keep]
    if len(taus) < 3:
        why = (
            "the signal does not vary: no noise to analyse"
            if not keep.any()
            else f"{x.size} samples give {len(taus)} tau(s); need 3: a longer record"
        )
        return AllanCurve(
            label, fs, x.size, taus, adev, math.nan, None, why, math.nan, math.nan, why
        )
    slopes = local_slopes(taus, adev)
    n, n_taus, n_reason = read_white(taus, adev, slopes)
    floor, floor_tau, b_reason = read_floor(taus, adev, slopes)
    return AllanCurve(
        label, fs, x.size, taus, adev, n, n_taus, n_reason, floor, floor_tau, b_reason
    )
