"""The transfer function twin -> device (Welch cross-spectra) and its reading per band.

Over the aligned overlap: H = P_xy / P_xx (x the twin, y the device) and the
magnitude-squared coherence, on the segments of :func:`.spectra.segment`. Each
judgeable band is read at its strongest twin bin: a gain of 0 dB and a
coherence near 1 there is a twin that matches the part; the calibration's
verdict reads the gain at the dominant tone from these (:mod:`.verdict`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal

from . import spectra
from .align import Alignment

__all__ = ["Transfer", "transfer"]


@dataclass(frozen=True)
class Transfer:
    """The transfer twin -> device at a band's strongest bin: where (Hz), gain (dB), phase
    (degrees), coherence."""

    at_hz: float
    gain_db: float
    phase_deg: float
    coherence: float


def transfer(
    a: Alignment, bands: np.ndarray, judged: list
) -> tuple[dict[tuple[int, int], Transfer], tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Per judgeable (axis, band) the transfer at its strongest bin; and the arrays
    (frequencies, H per axis, coherence per axis) for the figure."""
    nperseg = spectra.segment(a.rate_hz, a.twin.shape[1])
    f, pxy = signal.csd(a.twin, a.device, fs=a.rate_hz, nperseg=nperseg, axis=-1)
    _, pxx = signal.welch(a.twin, fs=a.rate_hz, nperseg=nperseg, axis=-1)
    _, coh = signal.coherence(a.twin, a.device, fs=a.rate_hz, nperseg=nperseg, axis=-1)
    out = {}
    for i, row in enumerate(judged):
        for b, (ok, _) in enumerate(row):
            inside = np.flatnonzero((f >= bands[b, 0]) & (f < bands[b, 2]))
            if not ok or not len(inside):
                continue
            k = inside[np.argmax(pxx[i, inside])]
            h = pxy[i, k] / pxx[i, k]
            out[(i, b)] = Transfer(
                at_hz=float(f[k]),
                gain_db=float(20 * np.log10(abs(h))),
                phase_deg=float(np.degrees(np.angle(h))),
                coherence=float(coh[i, k]),
            )
    return out, (f, pxy / np.where(pxx > 0, pxx, np.inf), coh)
