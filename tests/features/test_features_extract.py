"""The extractor's checks (STYLE item 7): inputs and outputs validated once, errors named."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from sdt_framework import FeatureSetSpec
from sdt_framework.api import extract
from sdt_framework.errors import SDTError
from sdt_framework.features import FeatureTable

FS = 3200.0
SIGNAL = np.random.default_rng(0).normal(size=(2, 320 + 3 * 2048))


def spec(compute: Callable[..., object], names: tuple[str, ...] = ("a", "b")) -> FeatureSetSpec:
    return FeatureSetSpec(
        name="probe", feature_names=names, units=("g",) * len(names), compute=compute
    )


def test_windows_reach_compute_centred_in_float64_and_table_has_indices() -> None:
    seen: dict[str, np.ndarray] = {}

    def compute(windows: np.ndarray, fs: float) -> np.ndarray:
        seen["w"] = windows
        return np.column_stack([windows.mean(axis=1), np.full(len(windows), fs)])

    table = extract(SIGNAL + 5.0, FS, spec(compute))
    assert seen["w"].dtype == np.float64 and seen["w"].shape == (6, 2048)
    np.testing.assert_allclose(table.values[:, 0], 0.0, atol=1e-6)  # mean-centred first
    np.testing.assert_array_equal(table.values[:, 1], FS)
    assert table.values.dtype == np.float32  # float64 accepted and cast
    np.testing.assert_array_equal(table.acquisition, [0, 0, 0, 1, 1, 1])
    np.testing.assert_array_equal(table.window, [0, 1, 2, 0, 1, 2])
    assert (table.feature_set, table.window_length, table.settle) == ("probe", 2048, 320)


def test_to_frame_columns_and_units() -> None:
    table = extract(SIGNAL, FS, spec(lambda w, fs: np.zeros((len(w), 2))))
    frame = table.to_frame()
    assert list(frame.columns) == ["acquisition", "window", "a", "b"]
    assert frame.attrs["units"] == {"a": "g", "b": "g"}
    assert isinstance(table, FeatureTable) and len(frame) == 6


def test_one_dimensional_input_is_one_acquisition() -> None:
    table = extract(SIGNAL[0], FS, spec(lambda w, fs: np.zeros((len(w), 2))))
    np.testing.assert_array_equal(table.acquisition, [0, 0, 0])


def test_nan_is_reported_with_its_position() -> None:
    x = SIGNAL.copy()
    x[1, 17] = np.nan
    with pytest.raises(SDTError, match=r"non-finite value nan at acquisition 1, sample 17"):
        extract(x, FS, spec(lambda w, fs: np.zeros((len(w), 2))))


def test_too_short_for_one_window() -> None:
    with pytest.raises(SDTError, match="needs 2368 samples"):
        extract(np.zeros(2000), FS, spec(lambda w, fs: np.zeros((len(w), 2))))


@pytest.mark.parametrize("shape", [(), (2, 2, 5000)])
def test_wrong_dimensions(shape: tuple[int, ...]) -> None:
    with pytest.raises(SDTError, match=r"1-D signal or a 2-D array"):
        extract(np.zeros(shape), FS, spec(lambda w, fs: np.zeros((len(w), 2))))


def test_complex_input_is_rejected() -> None:
    with pytest.raises(SDTError, match="real numbers"):
        extract(SIGNAL.astype(complex), FS, spec(lambda w, fs: np.zeros((len(w), 2))))


@pytest.mark.parametrize(
    ("compute", "message"),
    [
        (lambda w, fs: np.zeros(len(w)), r"shape \(6,\), expected \(6, 2\)"),
        (lambda w, fs: np.zeros((len(w), 3)), r"shape \(6, 3\), expected \(6, 2\)"),
        (lambda w, fs: np.full((len(w), 2), "x"), r"dtype <U1"),
        (lambda w, fs: None, r"dtype object"),
        (lambda w, fs: np.ones((len(w), 2)) * 1e300, r"feature 'a' is 1e\+300 in window 0"),
    ],
)
def test_bad_compute_output_names_the_feature_set(compute: Callable, message: str) -> None:
    with pytest.raises(SDTError, match=r"feature set 'probe' \(a, b\)") as info:
        extract(SIGNAL, FS, spec(compute))
    assert info.match(message)


def test_non_finite_output_names_the_feature_and_window() -> None:
    def compute(windows: np.ndarray, fs: float) -> np.ndarray:
        out = np.zeros((len(windows), 2))
        out[4, 1] = np.inf
        return out

    with pytest.raises(SDTError, match=r"feature 'b' is inf in window 4"):
        extract(SIGNAL, FS, spec(compute))


def test_exception_in_compute_keeps_traceback_and_gains_a_note() -> None:
    def compute(windows: np.ndarray, fs: float) -> np.ndarray:
        raise ZeroDivisionError("bug in the plugin")

    with pytest.raises(ZeroDivisionError) as info:
        extract(SIGNAL, FS, spec(compute))
    assert "while computing feature set 'probe'" in info.value.__notes__[0]
