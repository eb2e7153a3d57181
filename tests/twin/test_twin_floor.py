"""The quiet-segment floor (sdt_framework.twin.floor) on signals whose floor is known.

White noise of density N (g/sqrt(Hz)) has a flat one-sided PSD N^2; a burst of
broadband motion 40 dB above it must leave the segments it covers out of the
floor, and nothing else. Expected values come from N and the burst's times.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from sdt_framework.twin import floor

FS, SECONDS, N = 2000.0, 8.0, 100e-6


def _signal(burst: tuple[float, float] | None) -> np.ndarray:
    rng = np.random.default_rng(5)
    n = int(FS * SECONDS)
    x = N * np.sqrt(FS / 2) * rng.normal(size=(2, n))
    if burst is not None:
        t = np.arange(n) / FS
        inside = (t >= burst[0]) & (t < burst[1])
        x[:, inside] += 100 * N * np.sqrt(FS / 2) * rng.normal(size=(2, inside.sum()))
    return x


def test_a_stationary_record_keeps_every_segment_and_reads_its_floor():
    segments = floor.segmented(_signal(None), FS, floor.segments(SECONDS))
    quiet = segments.quiet(10, 800)
    assert quiet.all()  # 16 half-second segments, all within 3 dB of the quietest
    asd = segments.floor_asd(10, 800)
    assert np.all(np.abs(20 * np.log10(asd / N)) < 0.3)


def test_a_burst_is_left_out_and_the_floor_is_the_quiet_seconds():
    segments = floor.segmented(_signal((3.0, 5.2)), FS, floor.segments(SECONDS))
    quiet = segments.quiet(10, 800)
    starts = np.arange(quiet.shape[1]) * floor.SEGMENT_S
    touched = (starts + floor.SEGMENT_S > 3.0) & (starts < 5.2)  # segments the burst reaches
    assert np.array_equal(quiet, np.broadcast_to(~touched, quiet.shape))
    asd = segments.floor_asd(10, 800)
    assert np.all(np.abs(20 * np.log10(asd / N)) < 0.3)
    bands = np.array([[89.1, 100.0, 112.2], [354.8, 398.1, 446.7]])  # third octaves
    local, seconds = segments.local(bands, 10, 800)
    assert np.all(np.abs(10 * np.log10(local / N**2)) < 0.5)
    assert np.all(seconds == (~touched).sum() * floor.SEGMENT_S)


def test_the_median_bias_is_the_chi_square_median_over_its_mean():
    # a chi-square variable of k degrees of freedom over k: its median, drawn
    draws = stats.chi2(6).rvs(size=200_000, random_state=np.random.default_rng(1)) / 6
    assert floor.median_bias(6) == pytest.approx(np.median(draws), rel=0.01)
