"""Measures the synthetic pump's tests share, each as its source defines it."""

from __future__ import annotations

import numpy as np

FS = 20000.0


def measure(x: np.ndarray) -> dict[str, float]:
    """RMS, peak, Pearson kurtosis and crest factor, as the real statistics define them
    (tests/data/nln_emp_stats/README.md)."""
    rms = float(np.sqrt(np.mean(x * x)))
    squared = (x - x.mean()) ** 2  # squared twice, not ``** 4``: numpy's pow is 5x slower
    peak = float(np.max(np.abs(x)))
    kurtosis = float(np.mean(squared * squared) / np.mean(squared) ** 2)
    return {"rms_g": rms, "peak_g": peak, "kurtosis_pearson": kurtosis, "crest_factor": peak / rms}


def amplitude_near(x: np.ndarray, freq: float, tol: float = 0.03) -> float:
    """Amplitude of the sinusoid within freq*(1 +/- tol): Hann-windowed power summed over
    the band (Parseval), so it does not depend on where the line falls between bins."""
    w = np.hanning(x.size)
    spec = np.abs(np.fft.rfft(x * w)) ** 2
    f = np.fft.rfftfreq(x.size, 1 / FS)
    power = spec[(f > freq * (1 - tol)) & (f < freq * (1 + tol))].sum()
    return float(np.sqrt(4 * power / (x.size * np.sum(w * w))))
