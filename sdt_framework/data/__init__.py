"""Datasets: recordings with metadata (SPEC section 4).

Public API
----------
Recording, Dataset, Skipped, DataFileError
    Lazy recordings (metadata now, samples on ``load()``) and what was skipped.
open_dataset, load_dataset
    Open a registered dataset by name, an NLN-EMP folder or a manifest; load one
    dataset spec (a manifest gets the registry's signal readers, handed down).
open_manifest
    The manifest reader (registered as the plugin ``manifest``); the NLN-EMP
    reader and the synthetic pump's generator are their plugins' own packages
    (``plugins/datasets/nln_emp/``, ``plugins/datasets/synthetic_pump/``).
write_nln_emp ; synth_cost
    Write any dataset in the NLN-EMP CSV layout; what writing the synthetic one costs.
estimate_speeds, recording_speed, select_speeds
    Each recording's operating speed (given, or a tachless estimate named as such),
    and a dataset narrowed to some speeds (issue 43).
REQUIRED ; build_manifest, manifest_csv
    A manifest's required columns; a manifest built from a folder of signal files.

Signal files themselves (the readers' kit, one signal of one file) are a layer
below: :mod:`sdt_framework.signals`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lazy import lazy_exports

if TYPE_CHECKING:
    from .cache import ArrayCache, default_cache_dir
    from .manifest import REQUIRED, open_manifest
    from .manifest_build import build_manifest, manifest_csv
    from .open import load_dataset, open_dataset, write_nln_emp
    from .recording import DataFileError, Dataset, Recording, Skipped, measurement_groups
    from .sizes import synth_cost
    from .speed import estimate_speeds, recording_speed, select_speeds

#: public name -> the submodule that defines it. Loaded on first use (PEP 562), as
#: scipy loads its subpackages: a command that opens a manifest does not load
#: pyarrow's writer or the manifest's machinery at every ``sdt`` start
_WHERE = {
    "ArrayCache": "cache",
    "default_cache_dir": "cache",
    "REQUIRED": "manifest",
    "open_manifest": "manifest",
    "build_manifest": "manifest_build",
    "manifest_csv": "manifest_build",
    "load_dataset": "open",
    "open_dataset": "open",
    "write_nln_emp": "open",
    "DataFileError": "recording",
    "Dataset": "recording",
    "Recording": "recording",
    "Skipped": "recording",
    "measurement_groups": "recording",
    "synth_cost": "sizes",
    "estimate_speeds": "speed",
    "recording_speed": "speed",
    "select_speeds": "speed",
}

__all__ = [
    "REQUIRED",
    "ArrayCache",
    "DataFileError",
    "Dataset",
    "Recording",
    "Skipped",
    "build_manifest",
    "default_cache_dir",
    "estimate_speeds",
    "load_dataset",
    "manifest_csv",
    "measurement_groups",
    "open_dataset",
    "open_manifest",
    "recording_speed",
    "select_speeds",
    "synth_cost",
    "write_nln_emp",
]

__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())
