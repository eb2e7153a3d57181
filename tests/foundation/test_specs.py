"""Spec models: validation, immutability and the content hash."""

from __future__ import annotations

import pytest
from pydantic import ValidationError

from sdt_framework import ClassifierSpec, SensorSpec

BASE = dict(
    name="s1",
    sampling_rate_hz=3200,
    full_scale_g=16,
    adc_bits=13,
    noise_density_ug_rthz=290,
    mech_cutoff_hz=7000,
    analog_cutoff_hz=1600,
    digital_cutoff_hz=1599,
    digital_order=1,
)


def test_digital_cutoff_at_or_above_nyquist_is_rejected():
    with pytest.raises(ValidationError, match="at or above the Nyquist frequency 1600 Hz"):
        SensorSpec(**{**BASE, "digital_cutoff_hz": 1600})


def test_digital_cutoff_and_order_go_together():
    with pytest.raises(ValidationError, match="must be given together"):
        SensorSpec(**{**BASE, "digital_order": None})


def test_unknown_field_and_bad_name_are_rejected():
    with pytest.raises(ValidationError, match="Extra inputs are not permitted"):
        SensorSpec(**BASE, sample_rate=1)
    with pytest.raises(ValidationError, match="not a valid name"):
        SensorSpec(**{**BASE, "name": "My Sensor"})


def test_specs_are_frozen():
    spec = SensorSpec(**BASE)
    with pytest.raises(ValidationError):
        spec.adc_bits = 12  # type: ignore[misc]


def test_quantisation_step_is_two_full_scale_over_two_to_the_bits():
    assert SensorSpec(**BASE).quantisation_step_g == 32 / 8192


def test_content_hash_is_stable_and_ignores_provenance():
    a = SensorSpec(**BASE)
    b = SensorSpec(**BASE).model_copy(update={"plugin": "x", "distribution": "y"})
    c = SensorSpec(**{**BASE, "adc_bits": 12})
    assert a.content_hash() == b.content_hash()
    assert a.content_hash() != c.content_hash()
    assert len(a.content_hash()) == 64


def test_classifier_builds_fresh_estimators_with_seed():
    spec = ClassifierSpec(
        name="rf2",
        estimator="sklearn.ensemble:RandomForestClassifier",
        params={"n_estimators": 3},
    )
    a, b = spec.build(seed=1), spec.build(seed=1)
    assert a is not b
    assert a.get_params()["random_state"] == 1 and a.get_params()["n_estimators"] == 3


def test_classifier_import_path_is_checked():
    with pytest.raises(ValidationError, match="module:Class"):
        ClassifierSpec(name="bad", estimator="sklearn.ensemble.RandomForestClassifier")
