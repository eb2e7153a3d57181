"""Any recordings described by a CSV/Parquet manifest (files of any registered signal reader)."""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl


def _open(path, *, readers, **options):
    """Open the dataset, its files read by ``readers`` (the registry's, handed down by the
    caller); the reader is imported on use so listing plugins stays fast."""
    from sdt_framework.data import open_manifest

    return open_manifest(path, readers=readers, **options)


MANIFEST = DatasetSpec(
    name="manifest",
    description="Recordings listed in a manifest: path, rate, condition, severity, run, channel",
    source="sdt-framework manifest format (docs/data.md)",
    loader=_open,
    requires_path=True,
    reads_signal_files=True,
)


@hookimpl
def register_datasets(register):
    """Register the `manifest` dataset."""
    register(MANIFEST)
