"""SensorTwin, FeatureExtractor and window_rows against the framework's own API."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from sklearn.base import clone
from sklearn.linear_model import LogisticRegression
from sklearn.model_selection import GroupKFold, cross_val_score
from sklearn.pipeline import make_pipeline
from sklearn.preprocessing import StandardScaler

from sdt_framework import SDTError, UnknownNameError
from sdt_framework.api import degrade, extract
from sdt_framework.features import cut_windows
from sdt_framework.sklearn import FeatureExtractor, SensorTwin, row_noise_ids, window_rows

FS = 20000.0


@pytest.fixture(scope="module")
def acquisitions():
    """Three 2 s acquisitions of broadband vibration in g (1 g RMS), at 20 kHz."""
    return np.random.default_rng(7).normal(scale=1.0, size=(3, 40000))


def test_params_are_stored_as_given_and_clone(registry):
    spec = registry.sensor("adxl357")
    twin = SensorTwin(spec, fs=FS, seed=3, noise=False, settle_s=0.2)
    assert twin.get_params() == {
        "sensor": spec, "fs": FS, "seed": 3, "noise": False, "settle_s": 0.2,
    }  # fmt: skip
    assert clone(twin).get_params()["sensor"] == spec
    assert FeatureExtractor().get_params() == {"feature_set": "paper8", "fs": None}


def test_twin_equals_degrade_with_its_row_ids_minus_settling(registry, acquisitions):
    twin = SensorTwin("adxl345", fs=FS, seed=5).fit(acquisitions)
    y = twin.transform(acquisitions)
    expected, fs_out = degrade(
        acquisitions, FS, registry.sensor("adxl345"), seed=5,
        acquisition_ids=row_noise_ids(acquisitions),
    )  # fmt: skip
    assert fs_out == twin.fs_out_ == 3200
    np.testing.assert_array_equal(y, expected[:, 320:])
    assert y.shape == (3, (39999 * 3200) // 20000 + 1 - 320)
    assert twin.get_feature_names_out()[0] == "sensortwin0"


def test_row_noise_depends_on_the_row_only(acquisitions):
    twin = SensorTwin("adxl345", fs=FS, seed=1).fit(acquisitions)
    whole = twin.transform(acquisitions)
    np.testing.assert_array_equal(twin.transform(acquisitions[2:]), whole[2:])
    np.testing.assert_array_equal(twin.transform(acquisitions[::-1]), whole[::-1])
    quiet = SensorTwin("adxl345", fs=FS, seed=1, noise=False).fit_transform(acquisitions)
    other_seed = SensorTwin("adxl345", fs=FS, seed=2).fit_transform(acquisitions)
    assert not np.array_equal(whole, quiet) and not np.array_equal(whole, other_seed)
    assert len(set(row_noise_ids(acquisitions))) == 3


def test_feature_extractor_treats_each_row_as_one_window(registry, acquisitions):
    rows = acquisitions[:, :2048]
    fx = FeatureExtractor("paper8", fs=3200).fit(rows)
    values = fx.transform(rows)
    expected = extract(rows, 3200, registry.feature_set("paper8"), window_s=0.64, settle_s=0)
    np.testing.assert_array_equal(values, expected.values)
    assert values.dtype == np.float32 and values.shape == (3, 8)
    assert list(fx.get_feature_names_out()) == list(registry.feature_set("paper8").feature_names)


def test_set_output_pandas_names_the_features(acquisitions):
    pipe = make_pipeline(SensorTwin("adxl345", fs=FS), FeatureExtractor("paper8", fs=3200))
    frame = pipe.set_output(transform="pandas").fit_transform(acquisitions)
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == ["sigma", "S", "K", "CF", "A_RMS", "A_Peak", "V_RMS", "D_RMS"]
    assert len(frame) == 3


def test_window_rows_match_cut_windows_and_carry_groups(acquisitions):
    rows, groups = window_rows(acquisitions, FS, groups=["a", "a", "b"])
    cut = cut_windows(acquisitions, FS)  # 0.64 s windows after 0.1 s: 2 per 2 s acquisition
    assert rows.shape == (cut.n_windows, 2000 + 12800) == (6, 14800)
    np.testing.assert_array_equal(rows[:, 2000:], cut.data)  # the window, after its lead-in
    np.testing.assert_array_equal(rows[1, :2000], acquisitions[0, 12800:14800])
    assert list(groups) == ["a", "a", "a", "a", "b", "b"]
    with pytest.raises(SDTError, match="2 groups for 3 acquisitions"):
        window_rows(acquisitions, FS, groups=["a", "b"])
    with pytest.raises(SDTError, match="too short"):
        window_rows(acquisitions[:, :10000], FS)


def test_reference_pipeline_equals_benchmark_windows_exactly(registry, acquisitions):
    # The reference chain at 20 kHz is the identity, so twin + extractor on
    # window rows gives exactly the features of the benchmark's windows.
    rows, _ = window_rows(acquisitions, FS)
    pipe = make_pipeline(SensorTwin("wilcoxon-786b10", fs=FS), FeatureExtractor("paper8", fs=FS))
    expected = extract(acquisitions, FS, registry.feature_set("paper8")).values
    np.testing.assert_array_equal(pipe.fit_transform(rows), expected)


@pytest.mark.parametrize(("sensor", "fs_out"), [("adxl345", 3200.0), ("adxl357", 4000.0)])
def test_mems_pipeline_matches_whole_acquisition_chain(registry, acquisitions, sensor, fs_out):
    # Without noise, the only difference to degrading whole acquisitions is the
    # filters' state at the start of each row. The first window of an
    # acquisition starts from rest either way: bit-identical.
    rows, _ = window_rows(acquisitions, FS)
    pipe = make_pipeline(
        SensorTwin(sensor, fs=FS, noise=False), FeatureExtractor("paper8", fs=fs_out)
    )
    got = pipe.fit_transform(rows)
    whole, _ = degrade(acquisitions, FS, registry.sensor(sensor), noise=False)
    expected = extract(whole, fs_out, registry.feature_set("paper8")).values
    np.testing.assert_array_equal(got[::2], expected[::2])  # window 0 of each acquisition
    # Later windows: the 0.1 s lead-in settles ADXL357's filters completely; the
    # ADXL345's order-1 digital filter at 1599 Hz (fs 3200 Hz) has its pole at
    # z = -0.998 (time constant ~0.16 s), nearly cancelled by its zero at -1:
    # its start-up state still moves each feature by < 1 % of its typical size.
    scale = np.abs(expected).mean(axis=0)
    assert np.all(np.abs(got - expected) <= 1e-2 * scale)
    if sensor == "adxl357":
        np.testing.assert_array_equal(got, expected)


def test_pipeline_with_classifier_and_group_kfold(acquisitions):
    rows, groups = window_rows(np.vstack([acquisitions, 3 * acquisitions]), FS)
    labels = np.repeat(["quiet", "loud"], 6)
    pipe = make_pipeline(
        SensorTwin("adxl345", fs=FS),
        FeatureExtractor("paper8", fs=3200),
        StandardScaler(),
        LogisticRegression(),
    )
    scores = cross_val_score(pipe, rows, labels, groups=groups, cv=GroupKFold(n_splits=3))
    assert scores.shape == (3,) and np.all(scores == 1.0)  # 3x the RMS: trivially separable


def test_errors_name_the_problem(acquisitions):
    with pytest.raises(UnknownNameError, match="adxl35"):
        SensorTwin("adxl35", fs=FS).fit(acquisitions)
    with pytest.raises(SDTError, match=r"none left after settle_s=0\.1"):
        SensorTwin("adxl345", fs=FS).fit(acquisitions[:, :1000])
    with pytest.raises(ValueError, match="fs must be the rows' sampling rate"):
        FeatureExtractor("paper8").fit(acquisitions)
    with pytest.raises(ValueError, match="3 features"):
        SensorTwin("adxl345", fs=FS, settle_s=0).fit(acquisitions[:, :50]).transform(
            acquisitions[:, :3]
        )


def test_the_subpackage_named_sklearn_uses_scikit_learn():
    import sklearn

    import sdt_framework.sklearn as ours

    assert sklearn.__name__ == "sklearn" and sklearn.__file__ != ours.__file__
    assert issubclass(SensorTwin, sklearn.base.TransformerMixin)
    assert issubclass(FeatureExtractor, sklearn.base.BaseEstimator)
