"""Input checks of the measurement chain and the one error type they raise.

Every message is one line naming the sensor profile, the recording (its label)
and the offending value, so a user running a batch over many files knows at
once which file and which setting to fix (SPEC section 2, "Rules").
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..dtypes import describe_dtype, is_real
from ..errors import SDTError
from ..specs import SensorSpec

__all__ = [
    "ChainInputError",
    "ChainInputTypeError",
    "check_node",
    "check_rates",
    "check_signal",
]


class ChainInputError(SDTError):
    """A recording or a rate the chain cannot degrade (one line, names all three)."""

    def __init__(self, sensor: str, label: str, reason: str) -> None:
        self.sensor = sensor
        self.label = label
        self.reason = reason
        super().__init__(f"sensor {sensor!r}, recording {label or '<array>'!r}: {reason}")


class ChainInputTypeError(ChainInputError, TypeError):
    """Samples that are not real numbers (booleans, complex, objects, text): also a TypeError."""


def check_signal(x: ArrayLike, sensor: SensorSpec, label: str) -> NDArray[np.float64]:
    """Return ``x`` as a float64 array of 1 or 2 dimensions, or raise.

    Rejected: booleans, complex, object or text data, 0-D or 3-D+ arrays, empty signals,
    fewer than 2 samples (linear interpolation needs two), NaN or inf samples
    (their count and first index are reported).
    """
    arr = np.asarray(x)
    if not is_real(arr.dtype):
        raise ChainInputTypeError(
            sensor.name,
            label,
            f"samples must be real numbers (int or float), got {describe_dtype(arr.dtype)}; "
            f"convert x first, e.g. np.asarray(x, dtype=float)",
        )
    if arr.ndim not in (1, 2):
        raise ChainInputError(
            sensor.name,
            label,
            f"expected a 1-D signal or a 2-D batch (acquisitions x samples), "
            f"got a {arr.ndim}-D array of shape {arr.shape}",
        )
    if arr.size == 0:
        raise ChainInputError(sensor.name, label, f"empty signal (shape {arr.shape})")
    if arr.shape[-1] < 2:
        raise ChainInputError(
            sensor.name, label, f"{arr.shape[-1]} sample per acquisition; at least 2 are needed"
        )
    arr = arr.astype(np.float64, copy=False)
    finite = np.isfinite(arr)
    if not finite.all():
        bad = np.argwhere(~finite)
        first = tuple(int(i) for i in bad[0])
        where = first[0] if arr.ndim == 1 else first
        raise ChainInputError(
            sensor.name,
            label,
            f"{len(bad)} non-finite sample(s) (NaN or inf), first at index {where} "
            f"(value {arr[first]})",
        )
    return arr


def check_rates(fs: float, sensor: SensorSpec, label: str) -> float:
    """Check the recording rate ``fs`` against the sensor; return it as a float.

    Rejected: a non-positive or non-finite rate, a target rate above the
    recording's (the chain cannot invent bandwidth), and a digital cutoff at or
    above the target Nyquist (the spec validator rejects it too; this guards
    specs built with ``model_construct``).
    """
    fs = float(fs)
    if not math.isfinite(fs) or fs <= 0:
        raise ChainInputError(sensor.name, label, f"recording rate must be > 0 Hz, got {fs:g}")
    target = float(sensor.at_rate(fs).sampling_rate_hz)
    if target > fs:
        raise ChainInputError(
            sensor.name,
            label,
            f"target rate {target:g} Hz is above the recording's rate {fs:g} Hz; "
            f"the chain only lowers the rate",
        )
    cutoff = sensor.digital_cutoff_hz
    if cutoff is not None and cutoff >= target / 2:
        raise ChainInputError(
            sensor.name,
            label,
            f"digital cutoff {cutoff:g} Hz is at or above the target Nyquist {target / 2:g} Hz",
        )
    return fs


def check_node(
    other_axes: Mapping[str, ArrayLike], arr: NDArray[np.float64], sensor: SensorSpec, label: str
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """The node's other two axes as 2-D float64 batches shaped like ``arr``, or raise.

    ``other_axes`` maps two axis names (``"y"``, ``"z"``) to the same
    acquisitions recorded on those axes; each gets the checks of
    :func:`check_signal`.
    """
    if not isinstance(other_axes, Mapping) or len(other_axes) != 2:
        raise ChainInputError(
            sensor.name,
            label,
            "other_axes must map the node's other two axes to their signals, "
            "e.g. {'y': ay, 'z': az}",
        )
    batches = []
    for axis, values in other_axes.items():
        other = check_signal(values, sensor, f"{label or '<array>'}, axis {axis}")
        if other.shape != arr.shape:
            raise ChainInputError(
                sensor.name,
                label,
                f"axis {axis!r} holds shape {other.shape}, this axis {arr.shape}; "
                f"the three axes of a node must be recorded together",
            )
        batches.append(np.atleast_2d(other))
    return batches[0], batches[1]
