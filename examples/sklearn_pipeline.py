# %% [markdown]
# # The Sensor Digital Twin inside a scikit-learn pipeline
#
# Synthetic pump (the embedded default dataset), Motor-2, channel ch1: five
# classes (healthy, impeller, bearing bpfo, bearing bpfi, bearing pump), three
# physical runs each. Each acquisition is cut into one row per 0.64 s window
# (with a 0.1 s lead-in), a `SensorTwin` turns each row into what the sensor
# would have recorded, a `FeatureExtractor` computes the paper's 8 features,
# and a random forest classifies. Cross-validation is grouped by physical run,
# so windows of one run never sit on both sides. Two sensors are compared on
# the same folds and the same noise draws.
#
# Run it as a script (`python examples/sklearn_pipeline.py`) or cell by cell in
# an editor that understands `# %%`. SDT_EXAMPLE_DURATION_S sets the length of
# each synthetic acquisition (default 4 s; the test suite uses less).

# %%
from __future__ import annotations

import os

import numpy as np
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sklearn.ensemble import RandomForestClassifier
from sklearn.model_selection import GroupKFold, cross_val_score
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import StandardScaler

from sdt_framework import build_registry
from sdt_framework.sklearn import FeatureExtractor, SensorTwin, window_rows

DURATION_S = float(os.environ.get("SDT_EXAMPLE_DURATION_S", "4"))
FS_REF = 20000.0
SENSORS = ("adxl345", "adxl357")

# %% [markdown]
# ## Data: one row per window, one group per physical run

# %%
dataset = open_synthetic(machines="Motor-2", channels="ch1", duration=DURATION_S, seed=0)
parts, labels, groups = [], [], []
for recording in dataset.recordings():
    rows, row_groups = window_rows(
        recording.load(), FS_REF, groups=np.repeat(recording.run, recording.n_acquisitions)
    )
    parts.append(rows)
    labels += [recording.condition] * len(rows)
    groups.append(row_groups)
X = np.concatenate(parts)
y = np.asarray(labels)
run_of_row = np.concatenate(groups)
print(
    f"{X.shape[0]} windows of {X.shape[1]} samples, {len(set(y))} classes, "
    f"{len(set(run_of_row))} runs"
)

# %% [markdown]
# ## The pipeline: twin -> features -> scaling -> classifier

# %%
registry = build_registry()


def make_pipeline_for(sensor: str) -> Pipeline:
    """SDT of ``sensor`` on 20 kHz rows, paper8 at the sensor's rate, a random forest."""
    return Pipeline(
        [
            ("twin", SensorTwin(sensor, fs=FS_REF, seed=0)),
            ("features", FeatureExtractor("paper8", fs=registry.sensor(sensor).sampling_rate_hz)),
            ("scale", StandardScaler()),
            ("clf", RandomForestClassifier(n_estimators=100, random_state=0)),
        ]
    )


features = make_pipeline_for("adxl345")[:2].set_output(transform="pandas").fit_transform(X)
print(features.head())

# %% [markdown]
# ## Cross-validation by run, two sensors compared

# %%
cv = GroupKFold(n_splits=3)
scores = {
    sensor: cross_val_score(
        make_pipeline_for(sensor), X, y, groups=run_of_row, cv=cv, scoring="f1_macro"
    )
    for sensor in SENSORS
}
for sensor, values in scores.items():
    print(f"{sensor}: macro F1 {values.mean():.3f} ± {values.std():.3f} over {cv.n_splits} folds")
