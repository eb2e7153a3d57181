"""User features: the decorator, the hook, composition by name (SPEC section 3)."""

from __future__ import annotations

import types
from collections.abc import Callable

import numpy as np
import pytest
from sdt_plugins.features import paper8

from sdt_framework import FeatureSetSpec, Registry, build_registry, hookimpl
from sdt_framework.api import extract
from sdt_framework.errors import SDTError, UnknownNameError
from sdt_framework.features import Feature, feature, resolve_feature_set
from sdt_framework.hookspecs import Register

FS = 4000.0
X = np.random.default_rng(1).normal(size=(2, 400 + 2 * 2560))


@feature(name="peak_to_peak", unit="g", description="max - min")
def peak_to_peak(windows: np.ndarray, fs: float) -> np.ndarray:
    return windows.max(axis=1) - windows.min(axis=1)


def fresh_registry() -> Registry:
    return build_registry(entry_points=False, plugins=[paper8], environ={})


def test_decorator_makes_a_one_feature_spec_and_keeps_the_function() -> None:
    assert isinstance(peak_to_peak, Feature)
    spec = peak_to_peak.spec
    assert (spec.name, spec.feature_names, spec.units) == (
        "peak_to_peak",
        ("peak_to_peak",),
        ("g",),
    )
    assert spec.bytes_per_window == 4 and spec.description == "max - min"
    np.testing.assert_array_equal(peak_to_peak(np.array([[1.0, 3.0]]), 1.0), [2.0])
    assert "test_features_user" in spec.content_dict()["compute"]


def test_in_process_registration_and_extraction() -> None:
    registry = fresh_registry()
    registry.add(peak_to_peak.spec)
    table = extract(X, FS, registry.feature_set("peak_to_peak"))
    w = X[1, 400 + 2560 :]
    assert table.values.shape == (4, 1)
    np.testing.assert_allclose(table.values[3, 0], w.max() - w.min(), rtol=1e-6)


def test_decorator_can_register_at_once() -> None:
    registry = fresh_registry()

    @feature(name="zero", unit="1", registry=registry)
    def zero(windows: np.ndarray, fs: float) -> np.ndarray:
        return np.zeros(len(windows))

    assert registry.feature_set("zero").plugin == "(in-process)"


def test_registration_through_the_hook_like_paper8() -> None:
    plugin = types.ModuleType("my_features")

    @hookimpl
    def register_features(register: Register) -> None:
        register(peak_to_peak.spec)

    plugin.register_features = register_features
    registry = build_registry(entry_points=False, plugins=[paper8, plugin], environ={})
    assert registry.feature_set("peak_to_peak").plugin == "my_features"
    composed = resolve_feature_set(registry, "paper8 + peak_to_peak")
    assert composed.name == "paper8+peak_to_peak"


def test_composition_concatenates_columns_units_and_payload() -> None:
    registry = fresh_registry()
    registry.add(peak_to_peak.spec)
    composed = resolve_feature_set(registry, "paper8+peak_to_peak")
    assert composed.feature_names == (*paper8.PAPER8.feature_names, "peak_to_peak")
    assert composed.units[-1] == "g" and composed.bytes_per_window == 36
    both = extract(X, FS, composed).values
    np.testing.assert_array_equal(both[:, :8], extract(X, FS, paper8.PAPER8).values)
    np.testing.assert_array_equal(both[:, 8:], extract(X, FS, peak_to_peak.spec).values)
    assert resolve_feature_set(registry, "paper8") is registry.feature_set("paper8")
    assert composed.content_hash() != paper8.PAPER8.content_hash()


def test_duplicate_feature_names_across_parts_are_an_error() -> None:
    registry = fresh_registry()
    registry.add(
        FeatureSetSpec(
            name="my-stats",
            feature_names=("rms", "K"),
            units=("g", "1"),
            compute=lambda w, fs: np.zeros((len(w), 2)),
        )
    )
    with pytest.raises(SDTError, match=r"feature 'K' is provided by both 'paper8' and 'my-stats'"):
        resolve_feature_set(registry, "paper8+my-stats")
    with pytest.raises(SDTError, match="provided by both"):
        resolve_feature_set(registry, "paper8+paper8")


def test_unknown_or_empty_part() -> None:
    registry = fresh_registry()
    with pytest.raises(UnknownNameError, match=r"Did you mean 'paper8'"):
        resolve_feature_set(registry, "paper8+papr8")
    with pytest.raises(SDTError, match="empty part"):
        resolve_feature_set(registry, "paper8+")


@pytest.mark.parametrize(
    ("result", "message"),
    [
        (lambda w: np.zeros((len(w), 2)), r"feature 'bad' .* returned shape \(3, 2\)"),
        (lambda w: np.zeros(len(w) + 1), r"feature 'bad' .* returned shape \(4,\)"),
        (lambda w: np.array(["x"] * len(w)), r"feature set 'bad' \(bad\): compute returned dtype"),
        (lambda w: np.full(len(w), np.nan), r"feature 'bad' is nan in window 0"),
    ],
)
def test_misbehaving_user_feature_is_named(result: Callable, message: str) -> None:
    @feature(name="bad", unit="g")
    def bad(windows: np.ndarray, fs: float) -> np.ndarray:
        return result(windows)

    x = np.zeros(400 + 3 * 2560) + np.arange(400 + 3 * 2560) % 7
    with pytest.raises(SDTError, match=message):
        extract(x, FS, bad.spec)
    registry = fresh_registry()
    registry.add(bad.spec)
    with pytest.raises(SDTError, match=r"'bad'"):  # inside a composition, the part is named
        extract(x, FS, resolve_feature_set(registry, "paper8+bad"))
