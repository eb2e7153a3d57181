"""A signal's real time base: its rate measured from timestamps, and an even grid when needed.

Recorders timestamp their samples, and a part's real output rate differs from
its nominal one by a few percent (3134 Hz for an ADXL345 set to 3200 Hz). The
rate is the slope of a least-squares line through the timestamps. When a
timestamp strays from that line by more than :data:`EVEN_TOLERANCE` sample
periods (a clock step, a gap), the samples are resampled onto the even grid
by linear interpolation at their recorded times (the chain's own sampling
rule, SPEC stage 3), and a note says so; otherwise they are used as recorded.
Every reader of timestamped signals (IDE files, a pair's CSV with a time
column) goes through here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["EVEN_TOLERANCE", "EvenSignal", "measured_rate", "on_even_grid"]

#: largest distance (in sample periods) of a timestamp from the fitted line for "even"
EVEN_TOLERANCE = 1.0


@dataclass(frozen=True)
class EvenSignal:
    """Samples (rows) on an even grid: start, measured rate and its standard error, note."""

    values: np.ndarray
    start_s: float
    rate_hz: float
    rate_sd_hz: float
    note: str | None


def measured_rate(times: np.ndarray) -> tuple[float, float, float, float]:
    """(slope rate, median rate, largest distance of a timestamp from the line in periods,
    standard error of the slope rate from the timestamps' scatter about the line)."""
    if len(times) < 3:
        return float("nan"), float("nan"), 0.0, float("nan")
    index = np.arange(len(times), dtype=np.float64)
    slope, intercept = np.polyfit(index, times, 1)
    residual = times - (slope * index + intercept)
    stray = float(np.max(np.abs(residual)) / slope)
    slope_se = np.sqrt(residual @ residual / (len(times) - 2) / np.sum((index - index.mean()) ** 2))
    rate = 1.0 / float(slope)
    return rate, 1.0 / float(np.median(np.diff(times))), stray, float(slope_se * rate**2)


def on_even_grid(times: np.ndarray, values: np.ndarray, label: str) -> EvenSignal:
    """``values`` (rows, len(times)) on an even grid at the measured rate; ``label`` names
    the signal in the note."""
    rate, _, stray, rate_sd = measured_rate(times)
    start = float(times[0])
    if stray <= EVEN_TOLERANCE:
        return EvenSignal(values, start, rate, rate_sd, None)
    grid = start + np.arange(len(times)) / rate
    grid = grid[grid <= times[-1]]
    even = np.stack([np.interp(grid, times, row) for row in values])
    note = (
        f"{label}: timestamps stray up to {stray:.1f} sample periods from an even "
        f"{rate:.2f} Hz grid; resampled onto it (linear interpolation)"
    )
    return EvenSignal(even, start, rate, rate_sd, note)
