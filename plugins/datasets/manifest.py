"""Any recordings described by a CSV/Parquet manifest (CSV, NPY or MAT signal files)."""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl
from sdt_framework.data import open_manifest

MANIFEST = DatasetSpec(
    name="manifest",
    description="Recordings listed in a manifest: path, rate, condition, severity, run, channel",
    source="sdt-framework manifest format (docs/data.md)",
    loader=open_manifest,
    requires_path=True,
)


@hookimpl
def register_datasets(register):
    """Register the `manifest` dataset."""
    register(MANIFEST)
