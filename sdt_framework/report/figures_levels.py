"""Spectra by fault level: the ASD of healthy runs and of each level of one fault, per sensor.

An overlay of spectra ordered by fault level, not a waterfall (spectra over
time or speed): one panel per sensor, one colour per level (healthy black,
then the levels from dark to light), every test of a level drawn in its
colour, so that where a chain stops following the fault's growth is where its
levels stop separating.

Built to stay readable on a campaign's own data (issue 40: 42 files, three
tests per level): one legend for the whole figure, one entry per level with
its count of tests, outside the panels on the right, so that the panels keep
the figure's width; at most :data:`MAX_TESTS` tests of a level drawn (the
caption says how many there were); the y range is read from what each chain
passes and at most two decades below their typical floor (a decimating
part's stopband, or a DAQ's anti-alias skirt, reached 1e-13 g/√Hz and
squeezed every curve into the top of the panel), and the band above each
chain's bandwidth is shaded and named.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from matplotlib.figure import Figure

from ..chain import Passband
from ..severity import asd
from .signals import SensorTrace
from .style import figure_label, new_figure

__all__ = ["MAX_TESTS", "Level", "levels_figure"]

#: tests of one level drawn at most (the first ones, in run order)
MAX_TESTS = 5
#: the y range starts at the curves' 1st percentile in band, but at most this many decades
#: below their median (the typical floor): a DAQ's anti-alias skirt, which the chain of a
#: native reference does not know of, cannot pull the axis down to 1e-13
DECADES_BELOW_MEDIAN = 2.0
HEALTHY_COLOR = "0.1"


@dataclass(frozen=True)
class Level:
    """One level of the fault (or healthy): the traces of every sensor per test drawn."""

    label: str
    tests: Sequence[Sequence[SensorTrace]]
    total: int

    @property
    def legend(self) -> str:
        """``label (3 tests)``, or ``label (5 of 12 tests)`` when fewer were drawn."""
        drawn = len(self.tests)
        count = f"{drawn} of {self.total}" if drawn < self.total else f"{self.total}"
        return f"{figure_label(self.label, 28)} ({count} test{'s' if self.total != 1 else ''})"


def _level_colors(count: int) -> list:
    """Healthy black, then the fault levels from dark to light (matplotlib's plasma)."""
    from matplotlib import colormaps

    cmap = colormaps["plasma"]
    shades = np.linspace(0.1, 0.85, max(count - 1, 1))
    return [HEALTHY_COLOR, *(cmap(float(s)) for s in shades)][:count]


def _y_range(values: list[np.ndarray]) -> tuple[float, float]:
    """Bottom and top of a log axis from the in-band values of every curve of a panel."""
    joined = np.concatenate(values)
    joined = joined[np.isfinite(joined) & (joined > 0)]
    if joined.size == 0:
        return 1e-6, 1.0
    low = max(
        0.5 * float(np.percentile(joined, 1.0)), float(np.median(joined)) / 10**DECADES_BELOW_MEDIAN
    )
    return low, 2.0 * float(joined.max())


def levels_figure(
    levels: Sequence[Level],
    colors: dict[str, str],
    passbands: dict[str, Passband],
    title: str,
) -> tuple[Figure, list[str]]:
    """One panel per sensor: ASD of every drawn test of every level, one colour per level.

    ``levels`` runs healthy first, then the fault levels in order (each at most
    :data:`MAX_TESTS` tests, which the caller picks); ``passbands``
    gives each sensor's chain bandwidth (:func:`~.passband.passband`). Returns
    the figure and, per sensor, the spectrum's caption (scaling, window, RBW).
    """
    sensors = [t.sensor for t in levels[0].tests[0]]
    fig = new_figure(12.5, 2.4 * len(sensors) + 0.8)
    axes = fig.subplots(len(sensors), 1, squeeze=False, sharex=True)[:, 0]
    shades = _level_colors(len(levels))
    notes: dict[str, str] = {}
    handles, labels = [], []
    right = max(t.fs / 2 for level in levels for test in level.tests for t in test)
    for ax, sensor in zip(axes, sensors, strict=True):
        limit = passbands[sensor]
        in_band: list[np.ndarray] = []
        for level, shade in zip(levels, shades, strict=True):
            for k, traces in enumerate(level.tests):
                trace = next(t for t in traces if t.sensor == sensor)
                spec = asd(trace.signal, trace.fs)
                freq, values = spec.freq[1:], spec.values[1:]
                (line,) = ax.plot(freq, values, lw=0.7, color=shade, alpha=0.85)
                in_band.append(values[freq <= limit.top_hz])
                notes[sensor] = spec.caption()
                if k == 0 and ax is axes[0]:
                    handles.append(line)
                    labels.append(level.legend)
        if limit.top_hz < right:
            ax.axvspan(limit.top_hz, right, color="0.9", zorder=0)
            ax.text(
                0.995,
                0.04,
                f"above {limit.top_hz:.0f} Hz: beyond the chain's bandwidth",
                transform=ax.transAxes,
                ha="right",
                va="bottom",
                fontsize=7,
                color="0.35",
            )
        ax.set(xscale="log", yscale="log", ylim=_y_range(in_band), ylabel="ASD (g/√Hz)")
        ax.set_xlim(right=right)
        ax.set_title(figure_label(sensor), fontsize=9, loc="left", color=colors.get(sensor))
        ax.grid(alpha=0.3, which="major")
    axes[-1].set_xlabel("frequency (Hz)")
    fig.legend(handles, labels, loc="outside right upper", fontsize=8, title="level")
    fig.suptitle(title, fontsize=10)
    return fig, [f"{s}: {c}" for s, c in notes.items()]
