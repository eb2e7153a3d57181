"""The machines of a benchmark: its dataset's own, and the config's ``machine_specs`` over them.

The dataset describes its machines (:attr:`sdt_framework.data.Dataset.machines`:
the pump rig for ``synthetic-pump`` and ``nln-emp``, ``machines.toml`` beside a
manifest); ``machine_specs`` in the config gives a user's own, as the path of a
machine file or as ``[benchmark.machine_specs.NAME]`` tables
(:mod:`sdt_framework.machine_files`). A machine the config gives replaces the
dataset's of the same name (its ``origin`` names where it was read). Severity
and the report read the result: defect lines, bearing channels, zone tables.
"""

from __future__ import annotations

from ..data import Dataset
from ..machine_files import given_machines
from ..specs import MachineSpec
from .config import BenchmarkConfig

__all__ = ["benchmark_machines"]


def benchmark_machines(config: BenchmarkConfig, dataset: Dataset) -> dict[str, MachineSpec]:
    """The dataset's machines with the config's over them, by name."""
    return {**dataset.machines, **given_machines(config.machine_specs, "benchmark config")}
