"""Any recordings described by a CSV/Parquet manifest (files of any registered signal reader)."""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl


def _open(path, **options):
    """Open the dataset; the reader is imported on use so listing plugins stays fast."""
    from sdt_framework.data import open_manifest

    return open_manifest(path, **options)


MANIFEST = DatasetSpec(
    name="manifest",
    description="Recordings listed in a manifest: path, rate, condition, severity, run, channel",
    source="sdt-framework manifest format (docs/data.md)",
    loader=_open,
    requires_path=True,
)


@hookimpl
def register_datasets(register):
    """Register the `manifest` dataset."""
    register(MANIFEST)
