"""Random forest: the `rf` classifier with the paper's hyperparameters."""

from __future__ import annotations

from sdt_framework import ClassifierSpec, hookimpl

RF = ClassifierSpec(
    name="rf",
    description="Random forest (paper Table 3)",
    source="Paper Table 3; unnamed parameters at library defaults",
    estimator="sklearn.ensemble:RandomForestClassifier",
    params={"n_estimators": 100, "class_weight": "balanced"},
    seed_param="random_state",
)


@hookimpl
def register_classifiers(register):
    """Register the `rf` classifier."""
    register(RF)
