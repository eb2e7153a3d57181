"""Spectra of a pair: Welch PSDs, third-octave band RMS, noise floors, tones and THD.

Every estimate is Welch's (scipy.signal.welch / csd / coherence): Hann windows
of about one second (a power of two, :func:`segment`), half overlap, one-sided densities in
g^2/Hz. Band RMS is the square root of the density integrated over the band's
bins. A *floor* is the median amplitude density between ``lo`` and ``hi``
after the bins within three bins of any tone (a bin ten times the median
density or more) are dropped: the broadband level a tone and its harmonics do
not lift. ``sdt twin check`` reads its floors from the quiet time segments
instead (:mod:`.floor`), so that broadband motion is not taken for floor.
"""

from __future__ import annotations

import numpy as np
from scipy import signal

__all__ = ["band_rms", "floor_asd", "psd", "segment", "thd", "third_octaves", "tone_bins"]

#: a bin this many times the median density is a tone
TONE_FACTOR = 10.0


def segment(rate_hz: float, n: int) -> int:
    """Welch segment length: the power of two nearest one second, at most the signal."""
    return int(min(n, 2 ** round(np.log2(rate_hz))))


def psd(values: np.ndarray, rate_hz: float) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies, one-sided PSD per row) of ``values`` (rows: axes), mean removed."""
    nperseg = segment(rate_hz, values.shape[-1])
    return signal.welch(values, fs=rate_hz, nperseg=nperseg, detrend="constant", axis=-1)


def third_octaves(lo: float, hi: float) -> np.ndarray:
    """Rows (f_lower, f_centre, f_upper) of the base-10 third-octave bands inside [lo, hi]."""
    k = np.arange(np.floor(10 * np.log10(lo)) - 1, np.ceil(10 * np.log10(hi)) + 2)
    centre = 10 ** (k / 10)
    bands = np.stack([centre * 10**-0.05, centre, centre * 10**0.05], axis=1)
    return bands[(bands[:, 0] >= lo * 0.999) & (bands[:, 2] <= hi * 1.001)]


def band_rms(freqs: np.ndarray, density: np.ndarray, bands: np.ndarray) -> np.ndarray:
    """RMS per row and band (rows x bands): the density integrated over each band's bins."""
    df = freqs[1] - freqs[0]
    inside = (freqs[None, :] >= bands[:, :1]) & (freqs[None, :] < bands[:, 2:])
    return np.sqrt(density @ inside.T.astype(np.float64) * df)


def tone_bins(density: np.ndarray) -> np.ndarray:
    """Boolean mask of bins within three bins of a tone, per row."""
    median = np.median(density[..., 1:], axis=-1, keepdims=True)
    tones = density >= TONE_FACTOR * median
    near = tones.copy()
    for shift in (1, 2, 3):
        near[..., shift:] |= tones[..., :-shift]
        near[..., :-shift] |= tones[..., shift:]
    return near


def floor_asd(freqs: np.ndarray, density: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Median amplitude density (g/sqrt(Hz)) per row between ``lo`` and ``hi``, tones excluded."""
    band = (freqs >= lo) & (freqs <= hi)
    keep = band[None, :] & ~tone_bins(density)
    return np.array(
        [np.sqrt(np.median(row[mask])) for row, mask in zip(density, keep, strict=True)]
    )


def thd(freqs: np.ndarray, density: np.ndarray, f0: float, harmonics: int = 5) -> float:
    """Total harmonic distortion of the tone at ``f0``: sqrt(sum P_h) / sqrt(P_1), h = 2..5.

    Each P_h is the power within +-2 bins of h f0 (harmonics above the last bin are left
    out); NaN when the fundamental carries no power.
    """
    df = freqs[1] - freqs[0]

    def power(f: float) -> float:
        near = np.abs(freqs - f) <= 2.01 * df
        return float(density[near].sum() * df)

    fundamental = power(f0)
    orders = [h for h in range(2, harmonics + 1) if h * f0 <= freqs[-1]]
    if fundamental <= 0:
        return float("nan")
    return float(np.sqrt(sum(power(h * f0) for h in orders) / fundamental))
