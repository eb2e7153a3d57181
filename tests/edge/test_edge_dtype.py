"""A feature set's on-node dtype: payload, hashes, and rounding the features to it."""

from __future__ import annotations

import numpy as np
import pytest
from pydantic import ValidationError

from sdt_framework import FeatureSetSpec, SDTError
from sdt_framework.features import compose, feature, quantise_features


def _one(windows, fs):
    return windows[:, :1]


def _spec(**kwargs) -> FeatureSetSpec:
    return FeatureSetSpec(name="one", feature_names=("x",), units=("g",), compute=_one, **kwargs)


def test_bytes_per_value_follows_the_dtype():
    assert (_spec().dtype, _spec().bytes_per_value) == ("float32", 4)
    assert _spec(dtype="float16").bytes_per_value == 2
    assert _spec(bytes_per_value=2).dtype == "float16"  # a set written before dtype existed
    assert _spec(dtype="float16", bytes_per_value=2).bytes_per_window == 2
    with pytest.raises(ValidationError, match="contradicts"):
        _spec(dtype="float16", bytes_per_value=4)
    with pytest.raises(ValidationError, match="matches no dtype"):
        _spec(bytes_per_value=3)
    with pytest.raises(ValidationError, match="float16"):
        _spec(dtype="int8")


def test_with_dtype_halves_the_payload_and_changes_the_hash_only_when_it_changes(paper8):
    half = paper8.with_dtype("float16")
    assert (half.bytes_per_window, half.value_dtypes) == (16, ("float16",) * 8)
    assert half.name == "paper8" and half.plugin == paper8.plugin
    assert paper8.with_dtype("float32").content_hash() == paper8.content_hash()
    assert half.content_hash() != paper8.content_hash()
    assert "dtype" not in paper8.content_dict()  # float32 hashes as before dtype existed


def test_composed_sets_keep_each_parts_dtype(paper8):
    @feature(name="peak16", unit="g", dtype="float16")
    def peak16(windows, fs):
        """Largest absolute value."""
        return np.abs(windows).max(axis=1)

    mixed = compose([paper8, peak16.spec])
    assert mixed.value_dtypes == ("float32",) * 8 + ("float16",)
    assert mixed.bytes_per_window == 32 + 2
    all16 = mixed.with_dtype("float16")
    assert all16.value_dtypes == ("float16",) * 9 and all16.bytes_per_window == 18


def test_float32_features_pass_through_untouched(paper8):
    values = np.random.default_rng(0).normal(size=(5, 8)).astype(np.float32)
    assert quantise_features(values, paper8) is values


def test_float16_rounding_is_ieee_round_to_nearest(paper8):
    values = np.random.default_rng(1).lognormal(size=(50, 8)).astype(np.float32)
    out = quantise_features(values, paper8.with_dtype("float16"))
    assert out.dtype == np.float32
    np.testing.assert_array_equal(out, values.astype(np.float16).astype(np.float32))
    # relative error of float16 rounding is at most 2**-11 for normal numbers
    assert np.max(np.abs(out - values) / values) <= 2.0**-11
    assert not np.array_equal(out, values)


def test_only_the_float16_columns_are_rounded(paper8):
    @feature(name="peak16", unit="g", dtype="float16")
    def peak16(windows, fs):
        """Largest absolute value."""
        return np.abs(windows).max(axis=1)

    values = np.full((2, 9), 0.1, dtype=np.float32)
    out = quantise_features(values, compose([paper8, peak16.spec]))
    np.testing.assert_array_equal(out[:, :8], values[:, :8])
    assert out[0, 8] == np.float32(np.float16(0.1)) != np.float32(0.1)


def test_value_beyond_float16_range_is_an_error_naming_the_feature(paper8):
    values = np.ones((3, 8), dtype=np.float32)
    values[2, 7] = 70000.0  # D_RMS in um; float16 ends at 65504
    with pytest.raises(SDTError, match=r"'D_RMS' = 70000 in window 2 of rec-1 .*65504"):
        quantise_features(values, paper8.with_dtype("float16"), where="rec-1")
