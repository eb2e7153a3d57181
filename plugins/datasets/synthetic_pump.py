"""The embedded default dataset: a synthetic motor-pump rig, generated on demand."""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl


def _open(path, **options):
    """Open the dataset; the reader is imported on use so listing plugins stays fast."""
    from sdt_framework.data import open_synthetic

    return open_synthetic(path, **options)


SYNTHETIC_PUMP = DatasetSpec(
    name="synthetic-pump",
    description="Synthetic NLN-EMP-like pump rig: 2 machines, 14 classes, 5 channels, 20 kHz, g",
    source="sdt-framework physical model (docs/data.md); layout of NLN-EMP (Bruinsma 2024)",
    loader=_open,
    requires_path=False,
)


@hookimpl
def register_datasets(register):
    """Register the `synthetic-pump` dataset."""
    register(SYNTHETIC_PUMP)
