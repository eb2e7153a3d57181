"""Cut continuous acquisitions into analysis windows (paper section 2.3; SPEC section 3).

Each acquisition (one row of a 2-D array) first loses its settling interval
(the first ``round(settle_s * fs)`` samples, which hold the digital filters'
start-up transient), then its remainder is cut into non-overlapping windows of
``round(window_s * fs)`` samples; the tail shorter than one window is dropped.
Windows are cut per row, so a window never spans two acquisitions.

The cut is a slice and a reshape: no Python loop over windows. For a single
acquisition the result is a view of the input; for several it is one
vectorised copy (rows of different acquisitions are not equally spaced in
memory once the settling samples are removed).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..arguments import check_real
from ..errors import ArgumentValueError, SDTError, shown

__all__ = ["SETTLE_S", "WINDOW_S", "Windows", "cut_windows", "samples_for"]

#: Paper window length T_w, seconds (2048 samples at 3200 Hz, 12800 at 20 kHz).
WINDOW_S = 0.64
#: Settling interval discarded at the start of each acquisition, seconds.
SETTLE_S = 0.1


def samples_for(seconds: float, fs: float) -> int:
    """Number of samples in ``seconds`` at ``fs`` Hz, ``round(seconds * fs)``.

    A product that is not finite (``inf`` seconds, or 1e308 s at 3200 Hz) is an
    ArgumentValueError naming both, not an OverflowError from ``round``.
    """
    product = float(seconds) * float(fs)
    if not math.isfinite(product):
        raise ArgumentValueError(
            f"{shown(seconds)} s at {shown(fs)} Hz is not a finite number of samples; give a "
            f"finite duration in seconds"
        )
    return round(product)


@dataclass(frozen=True)
class Windows:
    """Windows cut from one or more acquisitions.

    Attributes
    ----------
    data
        Samples, shape (n_windows, length), the input's dtype.
    acquisition
        Row of the input each window comes from, shape (n_windows,), int64.
    window
        Index of the window within its acquisition, shape (n_windows,), int64.
    length
        Samples per window.
    settle
        Samples discarded at the start of each acquisition.
    """

    data: np.ndarray
    acquisition: np.ndarray
    window: np.ndarray
    length: int
    settle: int

    @property
    def n_windows(self) -> int:
        """Number of windows."""
        return int(self.data.shape[0])


def cut_windows(
    x: np.ndarray, fs: float, *, window_s: float = WINDOW_S, settle_s: float = SETTLE_S
) -> Windows:
    """Cut acquisitions into non-overlapping windows after the settling interval.

    Parameters
    ----------
    x
        One acquisition (1-D) or several (2-D, one per row), samples at ``fs``.
    fs
        Sampling rate, Hz.
    window_s
        Window length T_w, seconds; ``round(window_s * fs)`` samples.
    settle_s
        Interval discarded at the start of each acquisition, seconds.

    Returns
    -------
    Windows
        ``floor((n_samples - settle) / length)`` windows per acquisition, in
        acquisition order, then time order.

    Raises
    ------
    SDTError
        Wrong dimensions, a non-positive rate or window, or an acquisition too
        short for one window (the message says how many samples are needed);
        an infinite or NaN ``window_s``/``settle_s`` is an ArgumentValueError
        (also a ValueError).
    """
    x = np.asarray(x)
    if x.ndim == 1:
        x = x[np.newaxis, :]
    if x.ndim != 2:
        raise SDTError(
            f"expected a 1-D signal or a 2-D array (acquisitions x samples), got {x.ndim}-D "
            f"shape {x.shape}"
        )
    if not (np.isfinite(fs) and fs > 0):
        raise SDTError(f"sampling rate must be a positive number of Hz, got {shown(fs)}")
    for name, seconds, default in (
        ("window_s", window_s, WINDOW_S),
        ("settle_s", settle_s, SETTLE_S),
    ):
        if not math.isfinite(check_real(seconds, name, "seconds")):
            raise ArgumentValueError(
                f"{name} must be a finite number of seconds, got {shown(seconds)}; the paper's is "
                f"{default:g}"
            )
    length = samples_for(window_s, fs)
    settle = samples_for(settle_s, fs)
    if length < 1 or settle < 0:
        raise SDTError(
            f"window_s={shown(window_s)} s and settle_s={shown(settle_s)} s give {length} samples "
            f"per window and {settle} settling samples at {fs:g} Hz; need >= 1 and >= 0"
        )
    n_acq, n_samples = x.shape
    per_acq = max(n_samples - settle, 0) // length
    if per_acq == 0 or n_acq == 0:
        raise SDTError(
            f"acquisitions of {n_samples} samples are too short: one window at {fs:g} Hz needs "
            f"{settle + length} samples ({settle} settling + {length} window = "
            f"{settle_s:g} s + {window_s:g} s); give a longer signal or a shorter window"
        )
    used = x[:, settle : settle + per_acq * length]
    data = used.reshape(n_acq, per_acq, length).reshape(n_acq * per_acq, length)
    acquisition = np.repeat(np.arange(n_acq, dtype=np.int64), per_acq)
    window = np.tile(np.arange(per_acq, dtype=np.int64), n_acq)
    return Windows(data, acquisition, window, length, settle)
