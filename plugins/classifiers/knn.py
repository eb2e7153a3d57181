"""k-nearest neighbours: the `knn` classifier with the paper's hyperparameters."""

from __future__ import annotations

from sdt_framework import ClassifierSpec, hookimpl

KNN = ClassifierSpec(
    name="knn",
    description="k-nearest neighbours, distance-weighted (paper Table 3)",
    source="Paper Table 3; unnamed parameters at library defaults",
    estimator="sklearn.neighbors:KNeighborsClassifier",
    params={"n_neighbors": 5, "weights": "distance"},
    seed_param=None,
)


@hookimpl
def register_classifiers(register):
    """Register the `knn` classifier."""
    register(KNN)
