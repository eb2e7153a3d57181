"""The shaft's running speed read off a spectrum, away from mains lines, with its confidence.

A unit of its own at the bottom of the layers (it imports only numpy and
scipy), so every layer that needs a recording's speed reads it with this one
function: the data layer where a recording carries no speed
(:mod:`sdt_framework.data.speed`), features that work in orders of the running
speed, severity and the report placing defect lines (``severity`` re-exports
it).

The field places defect lines at the speed the machine ran, not at its
nameplate speed. The largest line within +-3 % of the nominal speed is that
speed on most machines, but not on a 2-pole motor on a 50 Hz (60 Hz) supply:
its shaft runs a slip below 50 Hz, and the supply's own line (electrical
pick-up, magnetic forces) sits within the same 3 %, often stronger. So lines
within a guard of every mains line and its harmonics (50 and 60 Hz, k x f up
to the search band) are not candidates: the guard is the Hann main lobe of
the unpadded spectrum (2 lines, fs / n each) plus a drift allowance (0.1 Hz
by default, a stated choice for a supply that is not exactly on its nominal
frequency, not a sourced grid figure). A shaft line inside a guard cannot be
told from the mains line; the estimate then says so.

:func:`estimate_running_speed` returns the estimate with what it rests on
(its line over the floor, the runner-up line, the 2x and 3x harmonics it
has); :func:`running_speed` only the frequency. A speed the user knows
(``given_hz``) is taken as given.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import numpy as np

__all__ = ["MAINS_HZ", "SpeedEstimate", "estimate_running_speed", "running_speed"]

#: the two public-supply frequencies; their harmonics are excluded from the search
MAINS_HZ = (50.0, 60.0)
PAD = 8  # zero-padding factor of the FFT the line is read from
LINE_DB = 10.0  # a candidate line stands this far above the floor (else: not a line)
HARMONIC_DB = 6.0  # a harmonic "supports" the line when it stands this far above the floor
AMBIGUOUS_DB = 3.0  # a runner-up within this of the line makes the choice ambiguous


@dataclass(frozen=True)
class SpeedEstimate:
    """A running speed and what it rests on.

    ``source``: "spectrum" (read off), "given" (the caller's) or "nominal"
    (nothing to read: no line outside the mains guards). ``snr_db``: the line
    over the median level of 0.5-1.5 x nominal; ``runner_up_db``: how far the
    next candidate line in the search band lies below it (inf if none);
    ``harmonics``: how many of 2x and 3x stand :data:`HARMONIC_DB` above that
    floor; ``excluded_hz``: the mains lines whose guards fell in the band;
    ``resolution_hz``: the line spacing of the unpadded spectrum.
    """

    hz: float
    source: Literal["spectrum", "given", "nominal"]
    snr_db: float = np.nan
    runner_up_db: float = np.nan
    harmonics: int = 0
    excluded_hz: tuple[float, ...] = field(default=())
    resolution_hz: float = np.nan
    reason: str = ""

    @property
    def confidence(self) -> Literal["high", "medium", "low", "none"]:
        """high: 20 dB over the floor, no runner-up within 6 dB and a harmonic; low: a
        runner-up within 3 dB; none: not read off the spectrum (nominal)."""
        if self.source != "spectrum":
            return "none" if self.source == "nominal" else "high"
        if self.runner_up_db < AMBIGUOUS_DB:
            return "low"
        if self.snr_db >= 20 and self.runner_up_db >= 6 and self.harmonics > 0:
            return "high"
        return "medium"

    def describe(self) -> str:
        """One line for a caption: the speed, its confidence and why."""
        rpm = f"{self.hz * 60:.0f} rpm ({self.hz:.3f} Hz)"
        if self.source != "spectrum":
            return f"{rpm}, {self.source}" + (f": {self.reason}" if self.reason else "")
        text = (
            f"{rpm} read off the spectrum, confidence {self.confidence}: line "
            f"{self.snr_db:.0f} dB over the floor, "
            + (
                f"next line {self.runner_up_db:.0f} dB below"
                if np.isfinite(self.runner_up_db)
                else "no other line"
            )
            + f" within the search band, {self.harmonics} of 2x/3x present"
        )
        if self.excluded_hz:
            text += f"; mains lines {', '.join(f'{f:g}' for f in self.excluded_hz)} Hz skipped"
        return text


def _guards(low: float, high: float, width: float, mains: tuple[float, ...]) -> list[float]:
    """The mains lines (and harmonics) whose guard overlaps ``low``-``high``."""
    lines = []
    for base in mains:
        k = np.arange(1, int((high + width) / base) + 1)
        lines += [float(f) for f in k * base if low - width <= f <= high + width]
    return sorted(set(lines))


def estimate_running_speed(
    x: np.ndarray,
    fs: float,
    nominal_hz: float,
    *,
    tolerance: float = 0.03,
    mains_hz: tuple[float, ...] = MAINS_HZ,
    drift_hz: float = 0.1,
    given_hz: float | None = None,
) -> SpeedEstimate:
    """The shaft speed: the largest line within ``tolerance`` of nominal, off the mains guards.

    Hann-windowed FFT zero-padded 8 times, parabolic interpolation on the log
    magnitude. ``mains_hz=()`` searches every line (a machine off the grid, on
    a drive); ``given_hz`` skips the search.
    """
    if given_hz is not None:
        return SpeedEstimate(float(given_hz), "given", reason="given by the caller")
    x = np.asarray(x, dtype=float)
    n = x.size
    size = PAD * n
    from scipy import ndimage, signal  # on use: a plugin importing PAD loads no scipy

    mag = np.abs(np.fft.rfft((x - x.mean()) * signal.windows.hann(n, sym=False), size))
    freq = np.fft.rfftfreq(size, 1 / fs)
    spacing = fs / n
    width = 2 * spacing + drift_hz
    low, high = nominal_hz * (1 - tolerance), nominal_hz * (1 + tolerance)
    excluded = _guards(low, high, width, mains_hz)
    near = (freq >= low) & (freq <= high)
    for line in excluded:
        near &= np.abs(freq - line) > width
    # candidate lines: maxima over their own main lobe (+-2 lines), so a side lobe of a
    # stronger line (a skipped mains line's) is not one
    lobe = 2 * PAD
    peak = mag == ndimage.maximum_filter1d(mag, 2 * lobe + 1, mode="nearest")
    floor = np.median(mag[(freq >= 0.5 * nominal_hz) & (freq <= 1.5 * nominal_hz)])
    candidates = np.flatnonzero(near & peak & (mag >= floor * 10 ** (LINE_DB / 20)))
    if candidates.size == 0:
        guards = ", ".join(f"{f:g}" for f in excluded)
        return SpeedEstimate(
            float(nominal_hz),
            "nominal",
            excluded_hz=tuple(excluded),
            resolution_hz=spacing,
            reason=f"no line stands {LINE_DB:g} dB over the floor within {100 * tolerance:g} % "
            f"of nominal"
            + (
                f" outside the mains guards (+-{width:.2f} Hz around {guards} Hz: the shaft "
                f"line may lie under a mains line)"
                if excluded
                else ""
            ),
        )
    order = candidates[np.argsort(mag[candidates])[::-1]]
    k = int(order[0])
    a, b, c = np.log(mag[k - 1 : k + 2] + 1e-300)
    shift = 0.5 * (a - c) / (a - 2 * b + c) if a - 2 * b + c != 0 else 0.0
    hz = float((k + shift) * fs / size)
    others = order[np.abs(freq[order] - hz) > 2 * spacing]
    runner = 20 * np.log10(mag[k] / mag[others[0]]) if others.size else np.inf
    support = 0
    for h in (2, 3):
        around = np.abs(freq - h * hz) <= 2 * spacing  # the harmonic's main lobe
        if around.any() and 20 * np.log10(mag[around].max() / floor) >= HARMONIC_DB:
            support += 1
    return SpeedEstimate(
        hz,
        "spectrum",
        snr_db=float(20 * np.log10(mag[k] / floor)),
        runner_up_db=float(runner),
        harmonics=support,
        excluded_hz=tuple(excluded),
        resolution_hz=spacing,
    )


def running_speed(x: np.ndarray, fs: float, nominal_hz: float, tolerance: float = 0.03) -> float:
    """The shaft speed in Hz (:func:`estimate_running_speed`, its frequency only)."""
    return estimate_running_speed(x, fs, nominal_hz, tolerance=tolerance).hz
