"""Issue 24, round 2, Python API: non-finite windows, part modes in ``degrade()``, seeds of
``SensorTwin``, and ties that divide by zero at a design point.

On main at e00f86b: ``extract(window_s=inf)`` raised an OverflowError (``nan``: a bare
ValueError from ``round``); ``degrade(x, fs, "adxl355[range=8g]")`` was an unknown sensor;
``SensorTwin(seed=1.7)`` ran with seed 1 and ``seed=True`` with seed 1; a tie dividing by
zero raised ZeroDivisionError out of the sweep.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from sdt_framework import build_registry
from sdt_framework.api import degrade, extract
from sdt_framework.errors import ArgumentTypeError, ArgumentValueError, SDTError
from sdt_framework.explore.ties import evaluate_tie
from sdt_framework.registry import default_registry
from sdt_framework.sklearn import SensorTwin


@pytest.fixture(autouse=True)
def fresh_default_registry(monkeypatch: pytest.MonkeyPatch):
    """Names resolve in a registry of the installed plugins, without switches."""
    for key in ("SDT_PLUGINS", "SDT_BLOCK_PLUGINS", "SDT_SENSOR_PATH"):
        monkeypatch.delenv(key, raising=False)
    default_registry.cache_clear()
    yield
    default_registry.cache_clear()


@pytest.mark.parametrize(
    ("argument", "value"),
    [
        ("window_s", math.inf),
        ("window_s", math.nan),
        ("settle_s", math.inf),
        ("settle_s", -math.inf),
    ],
)
def test_extract_refuses_a_non_finite_window_or_settling(argument, value):
    signal = np.random.default_rng(0).normal(size=8000)
    with pytest.raises(
        ArgumentValueError, match=rf"^{argument} must be a finite number of seconds"
    ):
        extract(signal, 3200.0, "paper8", **{argument: value})


def test_extract_refuses_a_window_whose_sample_count_overflows():
    signal = np.random.default_rng(0).normal(size=8000)
    with pytest.raises(ArgumentValueError, match=r"^1e\+308 s at 3200.0 Hz is not a finite"):
        extract(signal, 3200.0, "paper8", window_s=1e308)


def test_extract_with_a_label_names_it_in_a_signal_error():
    with pytest.raises(SDTError, match=r"^run-7\.npy: acquisitions of 100"):
        extract(np.zeros(100), 3200.0, "paper8", label="run-7.npy")


@pytest.mark.catalog
def test_degrade_resolves_a_part_in_a_mode_as_the_cli_does():
    """A 5 g sine through the ADXL355 at +-8 g keeps its peak; the default +-2 g clips it."""
    fs = 20000.0
    t = np.arange(int(fs)) / fs
    x = 5.0 * np.sin(2 * np.pi * 80.0 * t)
    wide, rate = degrade(x, fs, "adxl355[range=8g]", seed=0)
    narrow, _ = degrade(x, fs, "adxl355", seed=0)
    assert rate == 4000.0
    assert 4.8 < np.abs(wide).max() < 5.2
    assert np.abs(narrow).max() < 2.2
    spec = build_registry(environ={}).sensor("adxl355[range=8g]")
    by_spec, _ = degrade(x, fs, spec, seed=0)
    np.testing.assert_array_equal(wide, by_spec)


@pytest.mark.parametrize("seed", [1.7, True, "3", 2.0])
def test_sensor_twin_refuses_a_seed_that_is_not_an_integer(seed):
    twin = SensorTwin("adxl345", fs=20000.0, seed=seed)
    with pytest.raises(ArgumentTypeError, match=r"^seed must be an integer, got "):
        twin.fit(np.zeros((2, 20000)))


def test_a_tie_dividing_by_zero_at_a_point_is_a_value_error_naming_the_values():
    with pytest.raises(ValueError, match=r"is not a finite number at rate=800, bits=13"):
        evaluate_tie("rate / (bits - 13)", {"rate": 800.0, "bits": 13, "nsd": 1.0})
    assert evaluate_tie("rate / (bits - 12)", {"rate": 800.0, "bits": 13}) == 800.0
