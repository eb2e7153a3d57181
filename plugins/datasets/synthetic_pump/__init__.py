"""The embedded default dataset: a synthetic motor-pump rig, generated on demand.

The generator is this package: :mod:`.model` (the rig's constants, its speeds
and bearings read from ``../pump_rig.toml``), :mod:`.faults` (the fault
signatures), :mod:`.sources` (what the rig does in one acquisition),
:mod:`.mix` (each channel's level and impulsiveness from the real archive's
statistics), :mod:`.speeds` with ``speeds.toml`` (the machines at each speed and
their marks: ``marks.toml``, ``marks_motor2_50.toml``), :mod:`.generate` (one
run, every channel) and :mod:`.dataset` (the recordings, ``open_synthetic``).
Those modules are imported on use, so listing plugins stays fast.
"""

from __future__ import annotations

from sdt_framework import DatasetSpec, hookimpl
from sdt_framework.lazy import lazy_exports

_WHERE = {"open_synthetic": "dataset", "SyntheticPump": "dataset", "generate_run": "generate"}
__getattr__, __dir__ = lazy_exports(__name__, _WHERE, globals())


def _open(path, **options):
    """Open the dataset (the generator is imported here, on use)."""
    from .dataset import open_synthetic

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
