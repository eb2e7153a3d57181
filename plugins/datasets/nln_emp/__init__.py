"""The NLN-EMP motor-pump vibration dataset (4TU.ResearchData, CC0) in its published layout.

:mod:`.reader` walks the folder layout (``open_nln_emp``), :mod:`.csv_file`
parses its CSV files; the machines are the pump rig's (``../pump_rig.toml``).
Those modules are imported on use, so listing plugins stays fast.
"""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl
from sdt_framework.lazy import lazy_exports

_WHERE = {"PAPER_SUBSETS": "reader", "open_nln_emp": "reader", "parse_condition": "reader"}
__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())


def _open(path, **options):
    """Open the dataset (the reader is imported here, on use)."""
    from .reader import open_nln_emp

    return open_nln_emp(path, **options)


NLN_EMP = DatasetSpec(
    name="nln-emp",
    description="NLN-EMP CSV archive (Vibration/Motor-<k>/<speed>/<condition>/...-ch<c>.csv)",
    source="Bruinsma et al., Data in Brief 52 (2024); 4TU.ResearchData, CC0",
    loader=_open,
    requires_path=True,
)


@hookimpl
def register_datasets(register):
    """Register the `nln-emp` dataset."""
    register(NLN_EMP)
