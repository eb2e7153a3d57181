"""Windowing: counts, settling discard, acquisition boundaries, views (SPEC section 3)."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.features import cut_windows


@pytest.mark.parametrize(
    ("fs", "length", "settle"), [(3200, 2048, 320), (4000, 2560, 400), (20000, 12800, 2000)]
)
def test_twelve_second_acquisition_gives_18_windows(fs: int, length: int, settle: int) -> None:
    # floor((12 - 0.1) / 0.64) = 18 at every rate of the paper
    cut = cut_windows(np.zeros(12 * fs), fs)
    assert (cut.length, cut.settle, cut.n_windows) == (length, settle, 18)
    assert cut.data.shape == (18, length)
    np.testing.assert_array_equal(cut.window, np.arange(18))
    np.testing.assert_array_equal(cut.acquisition, np.zeros(18))


def test_windows_are_consecutive_samples_after_the_settling_interval() -> None:
    fs = 100.0  # 64 samples per window, 10 settling samples
    x = np.arange(10 + 3 * 64 + 5, dtype=float)
    cut = cut_windows(x, fs)
    assert cut.n_windows == 3
    np.testing.assert_array_equal(cut.data[0], np.arange(10, 74))
    np.testing.assert_array_equal(cut.data[2], np.arange(138, 202))  # tail of 5 dropped


def test_settling_marker_never_reaches_a_window() -> None:
    fs = 3200
    x = np.zeros((3, 12 * fs))
    x[:, : round(0.1 * fs)] = 1e6  # marker on every sample of the settling interval
    assert cut_windows(x, fs).data.max() == 0.0


def test_window_never_spans_two_acquisitions() -> None:
    fs = 3200
    # each acquisition holds its own index everywhere; 5000 samples = 2 windows + a tail
    x = np.repeat(np.arange(4.0)[:, None], 320 + 2 * 2048 + 500, axis=1)
    cut = cut_windows(x, fs)
    assert cut.n_windows == 8
    np.testing.assert_array_equal(cut.acquisition, [0, 0, 1, 1, 2, 2, 3, 3])
    np.testing.assert_array_equal(cut.window, [0, 1] * 4)
    assert np.all(cut.data.min(axis=1) == cut.data.max(axis=1))  # one acquisition per window
    np.testing.assert_array_equal(cut.data[:, 0], cut.acquisition)


def test_one_acquisition_is_cut_as_a_view() -> None:
    x = np.random.default_rng(0).normal(size=20000 * 2)
    cut = cut_windows(x, 20000)
    assert np.shares_memory(cut.data, x)


def test_window_and_settling_are_overridable() -> None:
    cut = cut_windows(np.zeros(10000), 1000, window_s=1.0, settle_s=0.0)
    assert (cut.length, cut.settle, cut.n_windows) == (1000, 0, 10)


def test_too_short_says_how_many_samples_are_needed() -> None:
    with pytest.raises(SDTError, match=r"needs 2368 samples \(320 settling \+ 2048 window"):
        cut_windows(np.zeros(2367), 3200)
    assert cut_windows(np.zeros(2368), 3200).n_windows == 1


@pytest.mark.parametrize("shape", [(), (2, 3, 40000)])
def test_wrong_dimensions(shape: tuple[int, ...]) -> None:
    with pytest.raises(SDTError, match=r"1-D signal or a 2-D array"):
        cut_windows(np.zeros(shape), 3200)


def test_bad_rate() -> None:
    with pytest.raises(SDTError, match="sampling rate"):
        cut_windows(np.zeros(5000), 0.0)
