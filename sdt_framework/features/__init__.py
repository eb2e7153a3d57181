"""Windowing and feature extraction (SPEC section 3).

Public API
----------
cut_windows, Windows
    Non-overlapping 0.64 s windows after a 0.1 s settling discard, per acquisition.
extract, FeatureExtractor, FeatureTable
    Validate a signal, window and centre it, compute a feature set, check the result;
    the feature set a spec (``sdt_framework.api.extract`` also takes its name, "paper8").
check_bands, check_order_bands, check_feature_output
    The checks extraction runs: declared frequency bands non-empty at the rate; order bands
    (a set in orders of the running speed) below Nyquist at the recording's speed; output.
feature, Feature
    Decorator turning ``f(windows, fs) -> (n_windows,)`` into a registrable feature.
compose, resolve_feature_set
    ``"paper8+env_bpfo"``: feature sets composed by name.
quantise_features
    Round features to their on-node dtype (float16 halves the payload), as the benchmark does.
read_feature_table, write_feature_table
    CSV / Parquet output with units attached.
"""

from __future__ import annotations

from .checks import check_bands, check_feature_output, check_order_bands
from .compose import ComposedFeatureSetSpec, compose, resolve_feature_set
from .extract import FeatureExtractor, extract
from .quantise import quantise_features
from .table import FeatureTable, read_feature_table, write_feature_table
from .user import Feature, feature
from .windowing import SETTLE_S, WINDOW_S, Windows, cut_windows, samples_for

__all__ = [
    "SETTLE_S",
    "WINDOW_S",
    "ComposedFeatureSetSpec",
    "Feature",
    "FeatureExtractor",
    "FeatureTable",
    "Windows",
    "check_bands",
    "check_feature_output",
    "check_order_bands",
    "compose",
    "cut_windows",
    "extract",
    "feature",
    "quantise_features",
    "read_feature_table",
    "resolve_feature_set",
    "samples_for",
    "write_feature_table",
]
