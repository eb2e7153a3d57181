"""The spectra-by-level figure stays readable with many tests per level (issue 40).

A campaign of three tests per level gave the old "severity waterfall" a
one-row legend wider than the figure: the panels were squeezed into a
quarter of its width, labels were cut, and a DAQ's anti-alias skirt pulled
the y axis down to 1e-13 g/√Hz.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from sdt_framework.chain import Passband
from sdt_framework.report.figures_levels import Level, levels_figure
from sdt_framework.report.signals import SensorTrace
from sdt_framework.report.style import save_figure, sensor_colors

from .conftest import assert_real_png

FLOOR = 1e-4  # g/√Hz: the white noise both sensors carry in band
FS_REF, FS_MEMS = 25600.0, 1344.0


def _trace(sensor: str, fs: float, level: int, test: int, cutoff: float) -> SensorTrace:
    """2 s of white noise at FLOOR, a 60 Hz line growing with the level, then a steep low-pass."""
    rng = np.random.default_rng(100 * level + test)
    t = np.arange(int(2 * fs)) / fs
    line = 0.01 * (level + 1) * np.sin(120 * np.pi * t)
    x = rng.normal(0, FLOOR * np.sqrt(fs / 2), t.size) + line
    # an elliptic low-pass 160 dB down: the anti-alias skirt of a DAQ (or a decimating part)
    sos = signal.ellip(10, 0.1, 160, cutoff, fs=fs, output="sos")
    return SensorTrace(sensor, signal.sosfilt(sos, x), fs, np.inf, 0.0)


@pytest.fixture(scope="module")
def campaign() -> list[Level]:
    """Healthy and four levels, three tests each, with the long run names of a TDMS campaign."""
    levels = []
    for level in range(5):
        tests = [
            [
                _trace("native-reference", FS_REF, level, k, 10000.0),
                _trace("lis3dh[mode=hr,odr=1344,range=2g]", FS_MEMS, level, k, 149.0),
            ]
            for k in range(3)
        ]
        label = "healthy" if level == 0 else f"cavitation_suction_{level}_test"
        levels.append(Level(label, tests, 3))
    return levels


def test_many_tests_per_level_keep_the_panels_wide_and_the_y_range_sane(campaign, tmp_path):
    sensors = ["native-reference", "lis3dh[mode=hr,odr=1344,range=2g]"]
    passbands = {
        sensors[0]: Passband(sensors[0], FS_REF / 2, "the recording's Nyquist frequency"),
        sensors[1]: Passband(sensors[1], 149.0, "its 149 Hz digital low-pass"),
    }
    fig, _ = levels_figure(campaign, sensor_colors(sensors, sensors[0]), passbands, "t")
    fig.canvas.draw()
    width = fig.bbox.width
    panels = [ax for ax in fig.axes if ax.get_ylabel()]
    assert len(panels) == 2
    for ax in panels:
        box = ax.get_window_extent()
        assert box.width > 0.6 * width, f"{ax.get_title(loc='left')}: {box.width / width:.0%}"
        bottom, top = ax.get_ylim()
        # measured independently: the in-band floor is FLOOR; the 60 Hz line reaches ~1e-2
        assert FLOOR / 1000 <= bottom <= FLOOR, bottom  # within 3 decades, not 9
        assert top > 0.01 * 5 / np.sqrt(2) / np.sqrt(1.5 * 2)
    (legend,) = fig.legends
    assert legend.get_window_extent().x1 <= width + 1  # inside the figure, not cut
    labels = [t.get_text() for t in legend.get_texts()]
    assert labels[0] == "healthy (3 tests)" and len(labels) == 5  # one entry per level
    # the band above the LIS3DH's bandwidth is shaded from 149 Hz on
    shaded = [p for p in panels[1].patches if p.get_x() == pytest.approx(149.0)]
    assert shaded
    assert_real_png(save_figure(fig, tmp_path, "levels.png"))
