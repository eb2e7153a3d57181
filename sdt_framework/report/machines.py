"""The machines a results folder's benchmark ran on: speeds, bearings, zone tables.

Read once per folder from its config (:func:`folder_machines`): the dataset
opened again, metadata only, for the machines it describes and the recordings
the spectral figures draw, with the config's ``machine_specs`` over them
(:func:`sdt_framework.bench.machines.benchmark_machines`). When the dataset
cannot be opened (the folder moved without its data), the config's own
machines are still read and :attr:`FolderMachines.problem` says why the rest
is missing. :func:`no_spec_line` is the one line the report and ``sdt
compare`` give for a machine without a spec.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..bench.machines import benchmark_machines
from ..data.recording import Recording
from ..errors import SDTError
from ..machine_files import given_machines
from ..specs import MachineSpec
from .load import ResultsFolder
from .signals import config_dataset, open_config_dataset

__all__ = ["FolderMachines", "folder_machines", "no_spec_line"]


@dataclass(frozen=True)
class FolderMachines:
    """The folder's machines by name, its recordings, and why the dataset was not read."""

    specs: dict[str, MachineSpec]
    recordings: list[Recording] = field(default_factory=list)
    problem: str = ""


def folder_machines(folder: ResultsFolder, registry: Any = None) -> FolderMachines:
    """The machines of ``folder``'s benchmark (kept on the folder after the first call)."""
    if folder.machines is not None:
        return folder.machines
    config = folder.config
    if config is None:
        folder.machines = FolderMachines({}, problem="config.toml is missing or invalid")
        return folder.machines
    if registry is None:
        from ..registry import build_registry

        registry = build_registry()
    try:
        dataset = config_dataset(config, registry)
        machines = FolderMachines(
            benchmark_machines(config, dataset), open_config_dataset(config, registry, dataset)
        )
    except SDTError as exc:
        problem = f"the dataset was not opened: {exc}"
        try:
            own = given_machines(config.machine_specs, folder.path / "config.toml")
        except SDTError as bad:
            own, problem = {}, f"{problem}; {bad}"
        machines = FolderMachines(own, problem=problem)
    folder.machines = machines
    return machines


def no_spec_line(machine: str) -> str:
    """What a machine without a spec lacks, and where to give one, in one line (plain text)."""
    return (
        f"{machine}: no machine spec, so no bearing defect lines and no default zone table: "
        f"give its shaft speed, bearings (geometry, channel, fault labels) and zone table in "
        f'machines.toml beside the manifest or under [benchmark.machine_specs."{machine}"] '
        f"(docs/severity.md, 'Your machine')"
    )
