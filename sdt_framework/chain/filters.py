"""Butterworth low-pass design for the chain, cached per (order, cutoff, rate).

Why a cache: a benchmark degrades thousands of acquisitions with the same few
(profile, rate) pairs; designing once and reusing keeps every acquisition on
exactly the same coefficients and costs nothing after the first call.

The skip rule (SPEC section 2): a filter whose cutoff is at or above the
Nyquist frequency of the rate it runs at is skipped, without a warning. A
digital filter cannot act there, and for the reference chain (30 kHz and 10 kHz
filters at 20 kHz) skipping is what leaves the recording unchanged.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
from numpy.typing import NDArray
from scipy.signal import butter, sosfreqz

__all__ = ["design_lowpass", "is_skipped", "lowpass_gain"]


def is_skipped(cutoff_hz: float, fs: float) -> bool:
    """True if a low-pass at ``cutoff_hz`` running at ``fs`` is skipped (cutoff >= fs/2)."""
    return cutoff_hz >= fs / 2


@lru_cache(maxsize=256)
def _design(order: int, cutoff_hz: float, fs: float) -> NDArray[np.float64] | None:
    if is_skipped(cutoff_hz, fs):
        return None
    sos = np.asarray(butter(order, cutoff_hz, btype="low", fs=fs, output="sos"), dtype=np.float64)
    sos.setflags(write=False)  # shared by every caller through the cache
    return sos


def design_lowpass(order: int, cutoff_hz: float, fs: float) -> NDArray[np.float64] | None:
    """Butterworth low-pass in second-order sections, or None when skipped.

    Parameters
    ----------
    order
        Filter order (a first-order filter is one section with b2 = a2 = 0).
    cutoff_hz
        -3 dB frequency, Hz.
    fs
        Rate the filter runs at, Hz; the design is bilinear
        (``scipy.signal.butter(..., fs=fs, output="sos")``).

    Returns
    -------
    numpy.ndarray or None
        Read-only ``(n_sections, 6)`` array, or None if ``cutoff_hz >= fs / 2``.
    """
    return _design(int(order), float(cutoff_hz), float(fs))


def lowpass_gain(
    sos: NDArray[np.float64] | None, freqs_hz: NDArray[np.float64], fs: float
) -> NDArray[np.float64]:
    """Magnitude response |H(f)| of ``sos`` at ``freqs_hz`` (1 for a skipped filter)."""
    freqs_hz = np.asarray(freqs_hz, dtype=np.float64)
    if sos is None:
        return np.ones_like(freqs_hz)
    _, h = sosfreqz(sos, worN=freqs_hz, fs=fs)
    return np.abs(h)
