"""Datasets: recordings with metadata (SPEC section 4).

Public API
----------
Recording, Dataset, Skipped, DataFileError
    Lazy recordings (metadata now, samples on ``load()``) and what was skipped.
open_dataset
    Open a registered dataset by name, an NLN-EMP folder or a manifest.
open_manifest
    The manifest reader (registered as the plugin ``manifest``); the NLN-EMP
    reader and the synthetic pump's generator are their plugins' own packages
    (``plugins/datasets/nln_emp/``, ``plugins/datasets/synthetic_pump/``).
write_nln_emp
    Write any dataset in the NLN-EMP CSV layout.
open_signal, FileSignal
    One signal of one file through the readers the caller hands down
    (``open_signal(file, registry.signal_readers())``), its rate and units
    settled against the file's: what ``sdt degrade`` and ``sdt features extract``
    read.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..lazy import lazy_exports

if TYPE_CHECKING:
    from .cache import ArrayCache, default_cache_dir
    from .manifest import open_manifest
    from .one_signal import FileSignal, open_signal
    from .open import open_dataset, write_nln_emp
    from .recording import DataFileError, Dataset, Recording, Skipped, measurement_groups

#: public name -> the submodule that defines it. Loaded on first use (PEP 562), as
#: scipy loads its subpackages: a signal reader that imports ``data.csv_signal`` does
#: not load pyarrow's writer or the manifest's machinery at every ``sdt`` start
_WHERE = {
    "ArrayCache": "cache",
    "default_cache_dir": "cache",
    "open_manifest": "manifest",
    "FileSignal": "one_signal",
    "open_signal": "one_signal",
    "open_dataset": "open",
    "write_nln_emp": "open",
    "DataFileError": "recording",
    "Dataset": "recording",
    "Recording": "recording",
    "Skipped": "recording",
    "measurement_groups": "recording",
}

__all__ = [
    "ArrayCache",
    "DataFileError",
    "Dataset",
    "FileSignal",
    "Recording",
    "Skipped",
    "default_cache_dir",
    "measurement_groups",
    "open_dataset",
    "open_manifest",
    "open_signal",
    "write_nln_emp",
]

__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())
