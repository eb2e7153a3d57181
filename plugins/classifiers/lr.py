"""Logistic regression: the `lr` classifier with the paper's hyperparameters."""

from __future__ import annotations

from sdt_framework import ClassifierSpec, hookimpl

LR = ClassifierSpec(
    name="lr",
    description="Logistic regression (paper Table 3)",
    source="Paper Table 3; unnamed parameters at library defaults",
    estimator="sklearn.linear_model:LogisticRegression",
    params={"max_iter": 2000, "class_weight": "balanced"},
    seed_param="random_state",
)


@hookimpl
def register_classifiers(register):
    """Register the `lr` classifier."""
    register(LR)
