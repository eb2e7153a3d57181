"""Machines written as TOML: the rig's file, a ``machines.toml`` beside a manifest, a config's.

A file holds one ``[machine.NAME]`` table per machine (NAME as the data names
it, quoted when it holds a dot or a space), each the
:class:`~sdt_framework.specs.MachineSpec` fields, its bearings as
``[[machine.NAME.bearings]]`` tables::

    [machine."pump-A"]
    shaft_rpm = 2950
    zone_table = "iso10816-3-group2-rigid"
    zone_why = "our 30 kW pump on a concrete block"

    [[machine."pump-A".bearings]]
    name = "6206"
    balls = 9
    ball_mm = 9.53
    pitch_mm = 46.0
    channel = "DE-h"
    faults = ["outer race"]

The benchmark config's ``machine_specs`` takes the same tables
(``[benchmark.machine_specs."pump-A"]``) or the path of such a file. A zone
table given as a relative ``FILE.toml`` in a file is read from that file's
folder. Every fault is one :class:`~sdt_framework.errors.SpecFileError` line
naming the file and the field.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from .errors import SpecFileError, one_line
from .specs import MachineSpec
from .toml_files import read_toml, validate_file

__all__ = [
    "MACHINE_FILE",
    "given_machines",
    "load_machine_file",
    "machines_from_tables",
    "spec_at_speeds",
]

#: the file beside a manifest that describes its machines
MACHINE_FILE = "machines.toml"
_UNKNOWN = "unknown field (the fields are in docs/severity.md, 'Your machine')"


def _zone_path(table: str | None, folder: Path | None) -> str | None:
    """A relative ``FILE.toml[#NAME]`` joined to ``folder``; a built-in name as given."""
    if table is None or folder is None:
        return table
    path, sep, name = table.partition("#")
    if not path.endswith(".toml") or os.path.isabs(path):
        return table
    return str(folder / path) + sep + name


def machines_from_tables(
    tables: Any, where: str | os.PathLike[str], prefix: str, folder: Path | None = None
) -> dict[str, MachineSpec]:
    """``NAME -> MachineSpec`` of ``tables`` (NAME -> fields) read from ``where``.

    ``prefix`` names the tables' place in errors (``machine.`` in a file,
    ``machine_specs.`` in a config); ``folder`` is where a relative zone-table
    path is read from (None: as given).
    """
    if not isinstance(tables, dict) or not tables:
        raise SpecFileError(
            where,
            prefix.rstrip("."),
            f"must hold one table per machine ([{prefix}NAME] with shaft_rpm = ...), got "
            f"{one_line(repr(tables), 60)}",
        )
    out = {}
    for name, table in tables.items():
        field = f"{prefix}{name}"
        if not isinstance(table, dict):
            raise SpecFileError(
                where, field, f"must be a table of machine fields, got {one_line(repr(table), 60)}"
            )
        if "name" in table and table["name"] != name:
            raise SpecFileError(
                where, f"{field}.name", f"{table['name']!r} differs from the table's name {name!r}"
            )
        if "origin" in table:
            raise SpecFileError(where, f"{field}.origin", "is set by sdt; remove the line")
        data = {**table, "name": name, "origin": str(where)}
        spec = validate_file(MachineSpec, data, where, prefix=f"{field}.", unknown=_UNKNOWN)
        out[name] = spec.model_copy(update={"zone_table": _zone_path(spec.zone_table, folder)})
    return out


def load_machine_file(path: str | os.PathLike[str]) -> dict[str, MachineSpec]:
    """Every machine of the machine file at ``path`` (its ``[machine.NAME]`` tables)."""
    path = Path(path)
    data = read_toml(path, what="machine file")
    unknown = sorted(set(data) - {"machine"})
    if unknown or "machine" not in data:
        found = f"; it has {', '.join(map(repr, unknown))}" if unknown else ""
        raise SpecFileError(
            path,
            unknown[0] if unknown else "machine",
            f"a machine file holds [machine.NAME] tables only{found} (docs/severity.md)",
        )
    return machines_from_tables(data["machine"], path, "machine.", path.parent)


def given_machines(
    given: str | dict[str, Any] | None, where: str | os.PathLike[str]
) -> dict[str, MachineSpec]:
    """The machines a config's ``machine_specs`` gives: a machine file's path (it names
    itself in an error) or NAME -> fields tables (``where``, the config, named); none
    for None."""
    if given is None:
        return {}
    if isinstance(given, str):
        return load_machine_file(Path(given).expanduser())
    return machines_from_tables(given, where, "machine_specs.")


def spec_at_speeds(
    name: str, spec: MachineSpec, speeds: Iterable[str]
) -> tuple[MachineSpec | None, str | None]:
    """``spec`` when machine ``name`` is recorded only at the speed it is for, else a note.

    A spec holds one operating point (the rig's Motor-2 at 100 %): its shaft
    speed and bearing lines do not hold at another speed, so a machine with
    recordings at another one (``speeds``: their % labels) gets no spec, and the
    note says what to give instead. Both pump datasets decide it here.
    """
    at = sorted(set(speeds), key=_by_number)
    if at == [f"{spec.speed_percent:g}"]:
        return spec, None
    return None, (
        f"{name}: the rig's machine spec is for {spec.speed_percent:g} % speed "
        f"({spec.shaft_rpm:g} rpm), the recordings are at {', '.join(at)} % (each carries its "
        f"speed_rpm): no machine spec (no defect lines, no default zone table); give one in the "
        f"config's [benchmark.machine_specs.{name}] (docs/severity.md)"
    )


def _by_number(label: str) -> tuple[int, float, str]:
    """Speed labels in numeric order (``50, 75, 100``), any other text after them."""
    try:
        return 0, float(label), label
    except ValueError:
        return 1, 0.0, label
