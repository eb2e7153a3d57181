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

A time base that is not one record is refused, not resampled: a timestamp
that goes back, an interval more than :data:`GAP_PERIODS` median periods long
(a gap, or a clock step such as idelib's reading of one block stamped a second
early as a 512 s clock wrap), or a slope rate and a median rate more than
:data:`RATE_AGREEMENT` apart (the rate changes within the recording). A
straight line through such timestamps is a wrong rate, and every figure
computed from it would be wrong with it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import SDTError

__all__ = [
    "EVEN_TOLERANCE",
    "GAP_PERIODS",
    "RATE_AGREEMENT",
    "EvenSignal",
    "measured_rate",
    "on_even_grid",
    "require_one_record",
]

#: largest distance (in sample periods) of a timestamp from the fitted line for "even"
EVEN_TOLERANCE = 1.0
#: an interval longer than this many median periods is a gap (real recorders: at most 1.2)
GAP_PERIODS = 10.0
#: largest relative difference of the slope rate and the median rate of one record
RATE_AGREEMENT = 0.1


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


def require_one_record(times: np.ndarray, label: str) -> None:
    """Refuse timestamps that go back, jump by more than :data:`GAP_PERIODS` periods, or whose
    slope and median rates disagree; ``label`` names the signal (its channel)."""
    if len(times) < 3:
        return
    steps = np.diff(times)
    period = float(np.median(steps))
    worst = int(np.argmax(np.abs(steps - period)))
    step = float(steps[worst])
    where = f"between samples {worst:,} and {worst + 1:,} (at {times[worst]:.4f} s)"
    if step <= 0 or step > GAP_PERIODS * period:
        what = f"go back by {-step:.4g} s" if step <= 0 else f"jump by {step:.4g} s"
        raise SDTError(
            f"{label}: timestamps {what} ({abs(step) / period:,.0f} sample periods) {where}: "
            f"a gap or a clock step, so the samples are not one even record; cut the "
            f"recording on one side of it"
        )
    rate, median, _, _ = measured_rate(times)
    if abs(rate / median - 1) > RATE_AGREEMENT:
        raise SDTError(
            f"{label}: the timestamps' slope gives {rate:.4g} Hz but their median interval "
            f"{median:.4g} Hz: the rate changes within the recording, so the samples are not "
            f"one even record; cut it where the rate changes"
        )


def on_even_grid(times: np.ndarray, values: np.ndarray, label: str) -> EvenSignal:
    """``values`` (rows, len(times)) on an even grid at the measured rate; ``label`` names
    the signal in the note. Timestamps that are not one record are refused
    (:func:`require_one_record`)."""
    require_one_record(times, label)
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
