"""The noise floor of a pair, from the time segments where nothing moves.

A floor is what a signal shows with no motion. The median density over
frequency of the whole record (what :func:`.spectra.floor_asd` gives) is that
floor only when the motion is a few tones: broadband random vibration or
shocks lift every bin, and the median then reads the motion. Here the record
is cut into segments of :data:`SEGMENT_S` seconds, each with its own Welch
spectrum (Hann windows of half a segment, half overlap: three per segment);
a segment's *level* is the median density of its tone-free bins in the band
of interest, and the floor is the mean spectrum of the *quiet* segments,
those within :data:`QUIET_FACTOR` (power) of the quietest. A stationary
record (a sine shaker, a part at rest) has every segment quiet, so the floor
is the plain Welch average; a shock or a burst of random vibration leaves
only the seconds around it out.

The median of a Welch density over bins reads low: each bin is the floor
times a chi-square variable of ``dof`` degrees of freedom over ``dof``, whose
median lies below 1. The floors returned are divided by that median
(:func:`median_bias`), with ``dof`` from the window's overlap correlation
(Welch 1967) times the number of quiet segments.

Device and twin floors are read over the same segments (by time) as the
reference's quiet ones, so the three floors describe the same seconds.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal, stats

from .spectra import TONE_FACTOR, tone_bins

__all__ = ["QUIET_FACTOR", "SEGMENT_S", "Segments", "median_bias", "segmented", "segments"]

#: length of one time segment, s (three Hann windows of a quarter second: 4 Hz bins)
SEGMENT_S = 0.5
#: a segment's level is ranked over at least this many bins (its scatter then ~15 %)
RANK_BINS = 24
#: a segment whose level is within this factor (power, 3 dB) of the quietest one is quiet
QUIET_FACTOR = 2.0


@dataclass(frozen=True)
class Segments:
    """Per-segment Welch densities of a signal (rows: axes), and the floors they give."""

    freqs: np.ndarray
    density: np.ndarray  # (rows, segments, bins) g^2/Hz
    segment_s: float
    dof: float  # degrees of freedom of one segment's density

    def quiet(self, lo: float, hi: float) -> np.ndarray:
        """(rows, segments) bool: the segments whose level (median of the tone-free bins
        between ``lo`` and ``hi``) is within :data:`QUIET_FACTOR` of the row's quietest."""
        band = (self.freqs >= lo) & (self.freqs <= hi)
        band = band if band.any() else np.ones_like(band)
        p = self.density[..., band]
        free = ~tone_bins(p)
        free |= ~free.any(axis=-1, keepdims=True)  # all tones: use every bin
        level = np.nanmedian(np.where(free, p, np.nan), axis=-1)
        return level <= QUIET_FACTOR * level.min(axis=1, keepdims=True)

    def _ranking_band(self, lo: float, hi: float) -> tuple[float, float]:
        """[lo, hi] widened (in ratio, about its centre) until it holds :data:`RANK_BINS`
        bins: a level from a handful of bins scatters so much that the quietest segment of
        a stationary record reads low, and the quiet mean with it."""
        df = self.freqs[1] - self.freqs[0]
        centre = np.sqrt(lo * hi)
        ratio = np.sqrt(hi / lo)
        while (min(centre * ratio, self.freqs[-1]) - centre / ratio) < RANK_BINS * df:
            if centre / ratio <= self.freqs[1] and centre * ratio >= self.freqs[-1]:
                break
            ratio *= 1.25
        return centre / ratio, centre * ratio

    def mean(self, mask: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(mean density (rows, bins) over each row's ``mask`` segments, its dof per row)."""
        n = mask.sum(axis=1)
        return (self.density * mask[..., None]).sum(axis=1) / n[:, None], self.dof * n

    def floor_asd(self, lo: float, hi: float, mask: np.ndarray | None = None) -> np.ndarray:
        """Floor amplitude density (g/sqrt(Hz)) per row between ``lo`` and ``hi``: the
        median of the tone-free bins of the quiet segments' mean (``mask``, default the
        quiet segments in that band), divided by the median's chi-square bias."""
        mask = self.quiet(lo, hi) if mask is None else mask
        density, dof = self.mean(mask)
        band = (self.freqs >= lo) & (self.freqs <= hi)
        return np.sqrt(_medians(density, band[None, :], dof))

    def local(self, bands: np.ndarray, lo: float, hi: float) -> tuple[np.ndarray, np.ndarray]:
        """Floor density (g^2/Hz) per row and band, and the quiet seconds it rests on
        (tones relative to the median between ``lo`` and ``hi``).

        For each band, the segments quiet within one octave either side of its centre;
        the median of their mean's tone-free bins there, divided by the median's
        chi-square bias (a floor rising toward low frequencies is not taken for motion).
        """
        rows = self.density.shape[0]
        out, seconds = np.zeros((rows, len(bands))), np.zeros((rows, len(bands)))
        span = (self.freqs >= lo) & (self.freqs <= hi)
        for b, centre in enumerate(bands[:, 1]):
            mask = self.quiet(*self._ranking_band(centre / 2, centre * 2))
            density, dof = self.mean(mask)
            near = (self.freqs >= centre / 2) & (self.freqs <= centre * 2)
            out[:, b] = _medians(density, near[None, :], dof, span)
            seconds[:, b] = mask.sum(axis=1) * self.segment_s
        return out, seconds


def _tones(density: np.ndarray, span: np.ndarray) -> np.ndarray:
    """Bins within three bins of a tone: a bin :data:`.spectra.TONE_FACTOR` times the
    median of the ``span`` bins or more (the median of the band analysed, not of the
    whole spectrum: a part's digital low-pass empties the bins above its corner, and a
    whole-spectrum median would then call the floor itself a tone)."""
    median = np.median(density[..., span], axis=-1, keepdims=True)
    return tone_bins(np.where(density >= TONE_FACTOR * median, np.inf, 0.0) + 1.0)


def _medians(density: np.ndarray, band: np.ndarray, dof: np.ndarray,
             span: np.ndarray | None = None) -> np.ndarray:  # fmt: skip
    """Per row, the median of the tone-free bins in ``band`` (tones relative to ``span``,
    default ``band``) over its chi-square bias."""
    keep = band & ~_tones(density, band[0] if span is None else span)
    out = np.zeros(density.shape[0])
    for i, row in enumerate(density):
        values = row[keep[i]] if keep[i].any() else row[band[0]]
        out[i] = np.median(values) / median_bias(dof[i]) if len(values) else 0.0
    return out


def median_bias(dof: float) -> float:
    """Median of a chi-square variable of ``dof`` degrees of freedom over ``dof`` (< 1)."""
    return float(stats.chi2.median(dof) / dof)


def segments(*spans_s: float) -> int:
    """How many whole :data:`SEGMENT_S` segments the shortest of the spans (s) holds; 1 when
    it holds none (the whole span is then one segment)."""
    return max(1, int(min(spans_s) // SEGMENT_S))


def _layout(n: int, rate_hz: float, count: int) -> tuple[int, int, int]:
    """(segment length, Welch window, hop) in samples for ``count`` segments of ``n``."""
    length = min(n // count, 2 * max(4, round(SEGMENT_S * rate_hz / 2)))
    window = max(2, length // 2)
    return 2 * window, window, window - window // 2


def _window_dof(window: int, hop: int, length: int) -> float:
    """Equivalent degrees of freedom of one segment's Welch average (Welch 1967, eq. 12)."""
    w = signal.get_window("hann", window)
    k = (length - window) // hop + 1
    total = 1.0
    for j in range(1, k):
        rho = (
            float(np.dot(w[j * hop :], w[: window - j * hop]) / np.dot(w, w))
            if j * hop < window
            else 0.0
        )
        total += 2 * (1 - j / k) * rho**2
    return 2 * k / total


def segmented(values: np.ndarray, rate_hz: float, count: int) -> Segments:
    """The Welch density of each of ``count`` consecutive segments of ``values``."""
    length, window, hop = _layout(values.shape[1], rate_hz, count)
    cut = values[:, : count * length].reshape(values.shape[0], count, length)
    f, p = signal.welch(cut, fs=rate_hz, nperseg=window, noverlap=window - hop,
                        detrend="constant", axis=-1)  # fmt: skip
    return Segments(f, p, length / rate_hz, _window_dof(window, hop, length))
