"""Datasets: recordings with metadata (SPEC section 4).

Public API
----------
Recording, Dataset, Skipped, DataFileError
    Lazy recordings (metadata now, samples on ``load()``) and what was skipped.
open_dataset, load_dataset
    Open a registered dataset by name, an NLN-EMP folder or a manifest; load one
    dataset spec (a manifest gets the registry's signal readers, handed down).
open_nln_emp, open_manifest, open_synthetic
    The three built-in readers (registered as plugins ``nln-emp``, ``manifest``,
    ``synthetic-pump``).
write_nln_emp
    Write any dataset in the NLN-EMP CSV layout.

Signal files themselves (the readers' kit, one signal of one file) are a layer
below: :mod:`sdt_framework.signals`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lazy import lazy_exports

if TYPE_CHECKING:
    from .cache import ArrayCache, default_cache_dir
    from .manifest import open_manifest
    from .nln_emp import PAPER_SUBSETS, open_nln_emp, parse_condition
    from .open import load_dataset, open_dataset, write_nln_emp
    from .recording import DataFileError, Dataset, Recording, Skipped, measurement_groups
    from .synth_dataset import SyntheticPump, open_synthetic

#: public name -> the submodule that defines it. Loaded on first use (PEP 562), as
#: scipy loads its subpackages: a command that opens a manifest does
#: not load the generator, and with it scipy.signal (about 1 s at every ``sdt`` start)
_WHERE = {
    "ArrayCache": "cache",
    "default_cache_dir": "cache",
    "open_manifest": "manifest",
    "PAPER_SUBSETS": "nln_emp",
    "open_nln_emp": "nln_emp",
    "parse_condition": "nln_emp",
    "load_dataset": "open",
    "open_dataset": "open",
    "write_nln_emp": "open",
    "DataFileError": "recording",
    "Dataset": "recording",
    "Recording": "recording",
    "Skipped": "recording",
    "measurement_groups": "recording",
    "SyntheticPump": "synth_dataset",
    "open_synthetic": "synth_dataset",
}

__all__ = [
    "PAPER_SUBSETS",
    "ArrayCache",
    "DataFileError",
    "Dataset",
    "Recording",
    "Skipped",
    "SyntheticPump",
    "default_cache_dir",
    "load_dataset",
    "measurement_groups",
    "open_dataset",
    "open_manifest",
    "open_nln_emp",
    "open_synthetic",
    "parse_condition",
    "write_nln_emp",
]

__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())
