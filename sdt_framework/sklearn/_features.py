"""``FeatureExtractor``: a feature set as a scikit-learn transformer, one window per row."""

from __future__ import annotations

import numpy as np
from sklearn.base import BaseEstimator, TransformerMixin
from sklearn.utils.validation import check_is_fitted, validate_data

from sdt_framework.api import resolve
from sdt_framework.features import extract
from sdt_framework.specs import FeatureSetSpec

__all__ = ["FeatureExtractor"]


def _resolve(feature_set: str | FeatureSetSpec) -> FeatureSetSpec:
    if isinstance(feature_set, FeatureSetSpec):
        return feature_set
    return resolve(FeatureSetSpec, str(feature_set), "feature_set")


class FeatureExtractor(TransformerMixin, BaseEstimator):
    """Features of each row, taken as one window: (n_rows, n_samples) -> (n_rows, n_features).

    Runs :func:`sdt_framework.features.extract` with the window set to the
    whole row and no settling discard, so every row is mean-centred and
    featurised exactly as the benchmark and ``sdt features extract`` do for a
    window of that length. To featurise long acquisitions window by window,
    cut them first with :func:`window_rows` (and a :class:`SensorTwin`, which
    drops the settling interval).

    Parameters
    ----------
    feature_set
        Registered or composed name (``"paper8"``, ``"paper8+env_bpfo"``) or a
        :class:`FeatureSetSpec`.
    fs
        Sampling rate of the rows, Hz (after a SensorTwin: the sensor's rate,
        ``twin.fs_out_``). Required.

    Attributes
    ----------
    feature_set_
        The resolved feature set; its ``units`` follow ``get_feature_names_out()``.

    Examples
    --------
    >>> FeatureExtractor("paper8", fs=3200).fit_transform(windows).shape  # doctest: +SKIP
    (n_windows, 8)
    """

    def __init__(self, feature_set: str | FeatureSetSpec = "paper8", fs: float | None = None):
        self.feature_set = feature_set
        self.fs = fs

    def fit(self, X, y=None):
        """Check ``X`` and ``fs``; resolve the feature set."""
        validate_data(self, X, dtype=np.float64)
        if self.fs is None or not (np.isfinite(self.fs) and self.fs > 0):
            raise ValueError(
                f"fs must be the rows' sampling rate in Hz (after a SensorTwin: its fs_out_), "
                f"got {self.fs!r}"
            )
        self.feature_set_ = _resolve(self.feature_set)
        return self

    def transform(self, X):
        """float32 features, one row per input row, in ``get_feature_names_out()`` order."""
        check_is_fitted(self, "feature_set_")
        X = validate_data(self, X, dtype=np.float64, reset=False)
        fs = float(self.fs)
        table = extract(X, fs, self.feature_set_, window_s=X.shape[1] / fs, settle_s=0.0)
        return table.values

    def get_feature_names_out(self, input_features=None):
        """The feature set's feature names (``sigma``, ``S``, ...)."""
        check_is_fitted(self, "feature_set_")
        return np.asarray(self.feature_set_.feature_names, dtype=object)

    def __sklearn_tags__(self):
        tags = super().__sklearn_tags__()
        tags.transformer_tags.preserves_dtype = []  # features are float32 (SPEC section 3)
        return tags
