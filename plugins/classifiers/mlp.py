"""Multilayer perceptron 256-128-64: the `mlp` classifier with the paper's hyperparameters."""

from __future__ import annotations

from sdt_framework import ClassifierSpec, hookimpl

MLP = ClassifierSpec(
    name="mlp",
    description="Multilayer perceptron 256-128-64 (paper Table 3)",
    source="Paper Table 3; unnamed parameters at library defaults",
    estimator="sklearn.neural_network:MLPClassifier",
    params={
        "hidden_layer_sizes": (256, 128, 64),
        "activation": "relu",
        "solver": "adam",
        "alpha": 0.005,
        "batch_size": 128,
        "learning_rate": "adaptive",
        "max_iter": 1500,
        "early_stopping": True,
        "validation_fraction": 0.1,
    },
    seed_param="random_state",
)


@hookimpl
def register_classifiers(register):
    """Register the `mlp` classifier."""
    register(MLP)
