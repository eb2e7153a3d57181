"""scikit-learn's own conformance suite on SensorTwin and FeatureExtractor.

Every check of ``parametrize_with_checks`` runs; none is marked as an expected
failure. scikit-learn itself skips ``check_array_api_input`` unless the
SCIPY_ARRAY_API environment variable is set (our transformers take numpy
arrays only, like the chain and the feature sets under them).

The checks feed small random matrices (rows of a few samples), so the twin is
checked with ``settle_s=0``: a 0.1 s settling interval needs more samples than
those rows hold (a clear error, tested in test_sklearn_transformers.py).
"""

from __future__ import annotations

from sklearn.utils.estimator_checks import parametrize_with_checks

from sdt_framework.sklearn import FeatureExtractor, SensorTwin

ESTIMATORS = [
    SensorTwin("adxl345", fs=20000, seed=0, settle_s=0.0),
    SensorTwin("wilcoxon-786b10", fs=20000, settle_s=0.0),
    FeatureExtractor("paper8", fs=3200),
]


@parametrize_with_checks(ESTIMATORS)
def test_sklearn_compatible(estimator, check):
    check(estimator)
