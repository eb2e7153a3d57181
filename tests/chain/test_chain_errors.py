"""Every input error of SPEC section 2, with its one-line message."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.chain import ChainInputError
from sdt_framework.errors import SDTError
from sdt_framework.specs import SensorSpec


def _message(exc: pytest.ExceptionInfo[ChainInputError]) -> str:
    text = str(exc.value)
    assert "\n" not in text
    assert isinstance(exc.value, SDTError)
    return text


def test_target_rate_above_the_recording_rate(adxl345: SensorSpec) -> None:
    with pytest.raises(ChainInputError) as exc:
        degrade(np.zeros(100), 2000, adxl345, label="pump.csv")
    assert _message(exc) == (
        "sensor 'adxl345', recording 'pump.csv': target rate 3200 Hz is above the "
        "recording's rate 2000 Hz; the chain only lowers the rate"
    )


def test_non_finite_samples_are_counted_and_located(adxl345: SensorSpec) -> None:
    x = np.zeros((3, 100))
    x[1, 42] = np.nan
    x[2, 7] = -np.inf
    with pytest.raises(ChainInputError) as exc:
        degrade(x, 20000, adxl345, label="run7")
    assert _message(exc) == (
        "sensor 'adxl345', recording 'run7': 2 non-finite sample(s) (NaN or inf), "
        "first at index (1, 42) (value nan)"
    )
    y = np.zeros(50)
    y[9] = np.inf
    with pytest.raises(ChainInputError, match=r"1 non-finite sample\(s\).*index 9 \(value inf\)"):
        degrade(y, 20000, adxl345)


@pytest.mark.parametrize("shape", [(0,), (3, 0), (0, 5)])
def test_empty_signal(adxl345: SensorSpec, shape: tuple[int, ...]) -> None:
    with pytest.raises(ChainInputError) as exc:
        degrade(np.zeros(shape), 20000, adxl345, label="e.npy")
    assert _message(exc) == f"sensor 'adxl345', recording 'e.npy': empty signal (shape {shape})"


def test_three_d_arrays_are_rejected(adxl345: SensorSpec) -> None:
    with pytest.raises(ChainInputError) as exc:
        degrade(np.zeros((2, 3, 4)), 20000, adxl345)
    assert _message(exc) == (
        "sensor 'adxl345', recording '<array>': expected a 1-D signal or a 2-D batch "
        "(acquisitions x samples), got a 3-D array of shape (2, 3, 4)"
    )


def test_digital_cutoff_at_target_nyquist_is_guarded(adxl345: SensorSpec) -> None:
    with pytest.raises(ValueError, match="at or above the Nyquist"):
        SensorSpec(**{**adxl345.content_dict(), "digital_cutoff_hz": 1600})
    bad = SensorSpec.model_construct(**{**adxl345.content_dict(), "digital_cutoff_hz": 1600.0})
    with pytest.raises(ChainInputError) as exc:
        degrade(np.zeros(100), 20000, bad, label="r")
    assert _message(exc) == (
        "sensor 'adxl345', recording 'r': digital cutoff 1600 Hz is at or above the "
        "target Nyquist 1600 Hz"
    )


@pytest.mark.parametrize(
    ("x", "fs", "needle"),
    [
        (np.zeros(1), 20000, "1 sample per acquisition; at least 2 are needed"),
        (np.array(["a", "b"]), 20000, "samples must be real numbers"),
        (np.zeros(4, dtype=complex), 20000, "samples must be real numbers"),
        (np.zeros(4), 0, "recording rate must be > 0 Hz, got 0"),
        (np.zeros(4), float("nan"), "recording rate must be > 0 Hz, got nan"),
        (np.float64(1.0), 20000, "got a 0-D array"),
    ],
)
def test_other_unusable_inputs(adxl345: SensorSpec, x: object, fs: float, needle: str) -> None:
    with pytest.raises(ChainInputError, match=needle.replace("(", r"\(").replace(")", r"\)")):
        degrade(x, fs, adxl345)
