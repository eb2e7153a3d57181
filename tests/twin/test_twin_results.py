"""The check's results are typed and frozen; the quantities the command line printed from
dicts (the rate against the part's setting, a scaled reference, a fitted profile's name)
are the twin package's own.

The rate settings are worked by hand from the recordings' figures the docs
print (docs/validation.md): the ADXL357 of DAQ12006 runs at 502.58 Hz, the
500 Hz setting of its 4000 Hz; XS5E25D40's at 4024.53 Hz, its 4000 Hz itself.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from sdt_framework.errors import SDTError
from sdt_framework.twin import (
    Band,
    CheckResult,
    Pair,
    Signal,
    check_twin,
    plot_check,
    profile_name,
    rate_setting,
    scaled_reference,
)
from sdt_framework.twin.results import plain

RATE = 3200.0


def _pair(seconds: float = 4.0) -> Pair:
    """A 160 Hz tone of 0.5 g on x seen by a quiet 20 kHz reference and a device at 3200 Hz."""
    gen = np.random.default_rng(7)
    t_ref = np.arange(int(seconds * 20000)) / 20000
    t_dev = np.arange(int(seconds * RATE)) / RATE
    tone = [0.5, 0.0, 0.0]
    ref = np.stack([a * np.sin(2 * np.pi * 160 * t_ref) for a in tone])
    dev = np.stack([a * np.sin(2 * np.pi * 160 * t_dev) for a in tone])
    ref = ref + 1e-6 * gen.standard_normal(ref.shape)
    dev = dev + 300e-6 * np.sqrt(RATE / 2) * gen.standard_normal(dev.shape)
    dev[2] += 1.0  # gravity on z
    xyz = ("x", "y", "z")
    return Pair("tone.npy", Signal("reference", "piezo", xyz, ref, 20000.0, 0.0),
                Signal("device", "adxl345", xyz, dev, RATE, 0.0), "0123456789ab")  # fmt: skip


@pytest.fixture(scope="module")
def result(registry) -> CheckResult:
    return check_twin(_pair(), registry.sensor("adxl345"))


def _dataclasses(value: object) -> list[object]:
    """Every dataclass instance in ``value``, at any depth (the figure's arrays aside)."""
    if dataclasses.is_dataclass(value):
        found = [value]
        for f in dataclasses.fields(value):
            if f.name != "spectra":
                found += _dataclasses(getattr(value, f.name))
        return found
    if isinstance(value, tuple | list):
        return [d for v in value for d in _dataclasses(v)]
    return []


def test_every_part_of_a_result_is_a_frozen_dataclass_holding_no_dict_or_list(result):
    parts = _dataclasses(result)
    kinds = {type(p).__name__ for p in parts}
    assert {"PairInfo", "AlignmentInfo", "Band", "Floor", "Distortion", "Clipping",
            "ClippedSide", "Calibration", "Summary", "Transfer"} <= kinds  # fmt: skip
    for part in parts:
        name = dataclasses.fields(part)[0].name
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(part, name, None)
        for f in dataclasses.fields(part):
            value = getattr(part, f.name)
            assert not isinstance(value, list), (type(part).__name__, f.name)
            if isinstance(value, dict):  # the one mapping: clipped samples per axis
                assert (type(part).__name__, f.name) == ("ClippedSide", "axes")
    assert all(isinstance(b, Band) for b in result.bands)


def test_the_json_form_keeps_the_declared_order_and_writes_no_nan(result):
    data = result.as_dict()
    assert list(data) == ["pair", "alignment", "bands", "floors", "distortion", "clipped",
                          "calibration", "summary"]  # fmt: skip
    assert list(data["pair"]["device"]) == ["channel", "part", "rate_hz", "nominal_rate_hz"]
    assert data["bands"][0]["axis"] == "x" and isinstance(data["alignment"]["signs"], list)
    assert plain({"a": (float("nan"), np.float64(np.inf), 1.5)}) == {"a": [None, None, 1.5]}


@pytest.mark.parametrize(
    ("rate", "nominal", "setting", "k", "shown"),
    [
        (502.58189825646554, 4000.0, 500.0, 3, "+0.52 % from the 500 Hz setting of 4000"),
        (4024.53, 4000.0, 4000.0, 0, "+0.61 % from 4000"),
        (3134.27, 3200.0, 3200.0, 0, "-2.05 % from 3200"),
        (9000.0, 4000.0, 4000.0, 0, "+125.00 % from 4000"),  # faster: no setting above nominal
    ],
)
def test_the_rate_is_read_against_the_parts_nearest_setting(rate, nominal, setting, k, shown):
    found = rate_setting(rate, nominal)
    assert (found.setting_hz, found.k) == (setting, k)
    assert found.error_pct == pytest.approx(100 * (rate / setting - 1), rel=1e-12)
    assert str(found) == shown


@pytest.mark.parametrize("nominal", [None, 0.0, -4000.0, math.inf, math.nan])
def test_no_setting_without_a_positive_nominal_rate(nominal):
    """The command line raised OverflowError on an infinite nominal rate."""
    assert rate_setting(1000.0, nominal) is None


def test_a_scaled_reference_is_multiplied_and_says_so():
    pair = _pair(1.0)
    assert scaled_reference(pair, 1.0) is pair
    scaled = scaled_reference(pair, 1.626)
    assert np.array_equal(scaled.reference.values, pair.reference.values * 1.626)
    assert scaled.reference.note == "reference values multiplied by 1.626 (--reference-scale)"
    assert scaled.device is pair.device


def test_a_fitted_profiles_name_is_one_sensor_finds_and_shadows_nothing(registry):
    base = registry.sensor("adxl345")
    assert profile_name(None, base, lambda name: False) == "adxl345-fitted"
    assert profile_name("mine.1", base, lambda name: False) == "mine.1"
    with pytest.raises(SDTError, match=r"--name 'Bad Name': a profile name is lower-case"):
        profile_name("Bad Name", base, lambda name: False)
    with pytest.raises(SDTError, match=r"already known .* e\.g\. adxl345-fitted-2$"):
        profile_name(None, base, lambda name: True)


def test_a_result_without_spectra_is_refused_by_the_figure(result, tmp_path):
    bare = dataclasses.replace(result, spectra=None)
    assert bare == result  # the arrays take no part in equality
    with pytest.raises(ValueError, match="nothing to draw"):
        plot_check(bare, tmp_path / "x.png")
