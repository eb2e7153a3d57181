"""Datasets: recordings with metadata (SPEC section 4).

Public API
----------
Recording, Dataset, Skipped, DataFileError
    Lazy recordings (metadata now, samples on ``load()``) and what was skipped.
open_dataset
    Open a registered dataset by name, an NLN-EMP folder or a manifest.
open_nln_emp, open_manifest, open_synthetic
    The three built-in readers (registered as plugins ``nln-emp``, ``manifest``,
    ``synthetic-pump``).
write_nln_emp
    Write any dataset in the NLN-EMP CSV layout.
"""

from __future__ import annotations

from .cache import ArrayCache, default_cache_dir
from .manifest import open_manifest
from .nln_emp import PAPER_SUBSETS, open_nln_emp, parse_condition
from .open import open_dataset, write_nln_emp
from .recording import DataFileError, Dataset, Recording, Skipped, measurement_groups
from .synth_dataset import SyntheticPump, open_synthetic

__all__ = [
    "PAPER_SUBSETS",
    "ArrayCache",
    "DataFileError",
    "Dataset",
    "Recording",
    "Skipped",
    "SyntheticPump",
    "default_cache_dir",
    "measurement_groups",
    "open_dataset",
    "open_manifest",
    "open_nln_emp",
    "open_synthetic",
    "parse_condition",
    "write_nln_emp",
]
