"""The NLN-EMP motor-pump vibration dataset (4TU.ResearchData, CC0) in its published layout."""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl


def _open(path, **options):
    """Open the dataset; the reader is imported on use so listing plugins stays fast."""
    from sdt_framework.data import open_nln_emp

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
