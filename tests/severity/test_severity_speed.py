"""The running speed of a 2-pole motor next to a stronger 50 Hz mains line (issue 40, item 3).

The signal is built here: a shaft line at a known speed a slip below 50 Hz,
its 2x and 3x, a mains line at 50.000 Hz three times stronger and its 100 Hz
(the magnetic forces' twice line frequency), and white noise. The expected
speed is the one put in.
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.severity import estimate_running_speed, running_speed

FS, SECONDS = 25600.0, 10.0
NOMINAL = 2950 / 60  # a 2-pole motor's nameplate speed on 50 Hz: 49.17 Hz, 50 Hz within 3 %


def _motor(shaft_hz: float | None, seed: int = 0) -> np.ndarray:
    t = np.arange(int(FS * SECONDS)) / FS
    x = 3.0 * np.sin(2 * np.pi * 50.0 * t) + 1.0 * np.sin(2 * np.pi * 100.0 * t)
    if shaft_hz is not None:
        for order, amplitude in ((1, 1.0), (2, 0.3), (3, 0.2)):
            x += amplitude * np.sin(2 * np.pi * order * shaft_hz * t + order)
    return x + 0.5 * np.random.default_rng(seed).standard_normal(t.size)


@pytest.mark.parametrize("shaft_hz", [49.17, 49.3, 49.6, 48.2])
def test_the_shaft_line_is_found_beside_a_stronger_mains_line(shaft_hz: float) -> None:
    x = _motor(shaft_hz)
    assert running_speed(x, FS, NOMINAL) == pytest.approx(shaft_hz, abs=0.005)  # main: 49.999
    estimate = estimate_running_speed(x, FS, NOMINAL)
    assert estimate.source == "spectrum" and estimate.excluded_hz == (50.0,)
    assert estimate.harmonics == 2 and estimate.confidence == "high"
    assert "mains lines 50 Hz skipped" in estimate.describe()


def test_a_shaft_line_under_the_mains_line_is_not_guessed() -> None:
    # 49.95 Hz lies within the 50 Hz guard (2 lines of 0.1 Hz + 0.1 Hz drift): no line to read
    for shaft in (49.95, None):
        estimate = estimate_running_speed(_motor(shaft), FS, NOMINAL)
        assert estimate.source == "nominal" and estimate.hz == NOMINAL
        assert estimate.confidence == "none"
        assert "the shaft line may lie under a mains line" in estimate.reason


def test_a_given_speed_is_taken_and_off_grid_machines_search_every_line() -> None:
    x = _motor(49.3)
    assert estimate_running_speed(x, FS, NOMINAL, given_hz=49.2).hz == 49.2
    # without the mains guard, the strongest line within 3 % is the mains line itself
    assert estimate_running_speed(x, FS, NOMINAL, mains_hz=()).hz == pytest.approx(50.0, abs=0.005)
