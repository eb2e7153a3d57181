"""XGBoost gradient-boosted trees: the `xgb` classifier with the paper's hyperparameters."""

from __future__ import annotations

from sdt_framework import ClassifierSpec, hookimpl

XGB = ClassifierSpec(
    name="xgb",
    description="XGBoost gradient-boosted trees (paper Table 3)",
    source="Paper Table 3; unnamed parameters at library defaults",
    estimator="xgboost:XGBClassifier",
    params={"n_estimators": 100, "learning_rate": 0.1, "max_depth": 5},
    seed_param="random_state",
)


@hookimpl
def register_classifiers(register):
    """Register the `xgb` classifier."""
    register(XGB)
