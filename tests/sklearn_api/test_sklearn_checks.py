"""scikit-learn's own conformance suite on SensorTwin and FeatureExtractor.

Every check of ``parametrize_with_checks`` runs; none is marked as an expected
failure. scikit-learn itself skips ``check_array_api_input`` unless the
SCIPY_ARRAY_API environment variable is set (our transformers take numpy
arrays only, like the chain and the feature sets under them).

The checks feed small random matrices (rows of a few samples), so the twin is
checked with ``settle_s=0``: a 0.1 s settling interval needs more samples than
those rows hold (a clear error, tested in test_sklearn_transformers.py).
The feature extractor is checked at fs = 2000 Hz: with rows of n >= 2 samples
its FFT bins (multiples of fs/n up to fs/2 = 1000 Hz) always fall in both of
paper8's bands (10 Hz to Nyquist, 10-1000 Hz); at 3200 Hz a 3-sample row has
one bin, at 1067 Hz, outside 10-1000 Hz, which extraction rightly refuses.
"""

from __future__ import annotations

from sklearn.utils.estimator_checks import parametrize_with_checks

from sdt_framework.sklearn import FeatureExtractor, SensorTwin

ESTIMATORS = [
    SensorTwin("adxl345", fs=20000, seed=0, settle_s=0.0),
    SensorTwin("wilcoxon-786b10", fs=20000, settle_s=0.0),
    FeatureExtractor("paper8", fs=2000),
]


@parametrize_with_checks(ESTIMATORS)
def test_sklearn_compatible(estimator, check):
    check(estimator)
