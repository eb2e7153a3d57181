"""The Sensor Digital Twin and the feature sets as scikit-learn transformers.

Public API
----------
SensorTwin(sensor="adxl345", fs=20000, seed=0)
    Rows of a reference signal -> what the sensor would have recorded of them.
FeatureExtractor(feature_set="paper8", fs=...)
    Rows (each one window) -> feature matrix, ``get_feature_names_out()``.
window_rows(X, fs, groups=...)
    Long acquisitions -> one row per window (with a lead-in) and the
    row-to-group labels for ``GroupKFold``.
row_noise_ids(X)
    The per-row noise ids SensorTwin uses (to reproduce it with ``chain.degrade``).

Example::

    from sklearn.ensemble import RandomForestClassifier
    from sklearn.model_selection import GroupKFold, cross_val_score
    from sklearn.pipeline import make_pipeline

    rows, groups = window_rows(acquisitions, 20000, groups=run_of_acquisition)
    pipe = make_pipeline(
        SensorTwin("adxl345", fs=20000), FeatureExtractor("paper8", fs=3200),
        RandomForestClassifier(random_state=0),
    )
    cross_val_score(pipe, rows, labels, groups=groups, cv=GroupKFold(3))

This subpackage is named ``sklearn`` but imports scikit-learn absolutely
(``from sklearn.base import ...`` always means scikit-learn).
"""

from __future__ import annotations

from ._features import FeatureExtractor
from ._twin import SensorTwin, row_noise_ids
from ._windows import window_rows

__all__ = ["FeatureExtractor", "SensorTwin", "row_noise_ids", "window_rows"]
