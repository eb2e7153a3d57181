"""Which zone table grades which machine: the machine's spec, a config, --zones.

A machine's spec (:class:`~sdt_framework.specs.MachineSpec`: the dataset's
machines, a ``machines.toml`` beside a manifest, the config's
``machine_specs``) names its table and why (the pump rig's file names the pump
end's proxy); the config's ``[benchmark] zones`` and ``--zones`` override it.
A table whose band is not the windows' V_RMS band (a 2-1000 Hz table) is
refused here, before any run, with the reason (:func:`.tables.band_problem`),
as is a table name that does not resolve.
"""

from __future__ import annotations

from collections.abc import Mapping

from ..errors import SDTError
from ..specs import MachineSpec
from .tables import Assignment, ZoneTable, band_problem, resolve_table

__all__ = ["Assignment", "assign_tables", "spec_tables"]


def _gradable(table: ZoneTable, where: str, window_s: float | None) -> ZoneTable:
    problem = band_problem(table, window_s)
    if problem:
        raise SDTError(f"{where}: {problem}")
    return table


def spec_tables(
    specs: Mapping[str, MachineSpec], window_s: float | None = None
) -> dict[str, Assignment]:
    """The table each machine's spec names, and why; a name that does not resolve, or a
    table that cannot grade the windows, is one line naming the spec's file and field."""
    out = {}
    for name, spec in specs.items():
        if spec.zone_table is None:
            continue
        where = f"{spec.origin or 'machine spec'}: machine {name!r} field 'zone_table'"
        try:
            table = resolve_table(spec.zone_table)
        except SDTError as exc:
            raise SDTError(f"{where}: {exc}") from None
        reason = spec.zone_why or f"named by the machine's spec ({spec.origin})"
        out[name] = Assignment(name, _gradable(table, where, window_s), reason)
    return out


def assign_tables(
    machines: list[str],
    choices: list[str] = (),
    configured: Mapping[str, str] | None = None,
    where: str = "[benchmark] zones",
    window_s: float | None = None,
    specs: Mapping[str, MachineSpec] | None = None,
) -> dict[str, Assignment]:
    """The table for each machine: ``choices`` ("TABLE" or "MACHINE=TABLE", ``--zones``),
    else ``configured`` (the benchmark config's ``zones``, MACHINE -> TABLE), else the one
    its spec in ``specs`` names (:func:`spec_tables`).

    A machine with none of them (a user's dataset without a machine spec) gets
    no table and is left out of the severity figures; the caller says so. A
    configured machine that is not in ``machines``, a table that does not
    resolve or one that cannot grade the windows' V_RMS (its band) is one line
    naming ``where`` (the config file) and the field, or the spec's file;
    ``window_s`` (the windows' length) goes into that line.
    """
    from_specs = spec_tables(specs or {}, window_s)
    chosen: dict[str, tuple[str, str]] = {}
    for machine, table in (configured or {}).items():
        if machine not in machines:
            raise SDTError(
                f"{where}: {machine}: no machine {machine!r} here; machines are "
                f"{', '.join(machines)} (fix the name or remove the line)"
            )
        try:
            resolve_table(table)
        except SDTError as exc:
            raise SDTError(f"{where}: {machine}: {exc}") from None
        _gradable(resolve_table(table), f"{where}: {machine}", window_s)
        chosen[machine] = (table, "given in the benchmark config ([benchmark] zones)")
    for choice in choices:
        machine, sep, table = choice.rpartition("=")
        if sep and machine not in machines:
            raise SDTError(
                f"--zones {choice!r}: no machine {machine!r} in the results; "
                f"machines are {', '.join(machines)}"
            )
        _gradable(resolve_table(table), f"--zones {choice!r}", window_s)
        for target in [machine] if sep else machines:
            chosen[target] = (table, "given (--zones)")
    out: dict[str, Assignment] = {}
    for machine in machines:
        if machine in chosen:
            table, reason = chosen[machine]
            out[machine] = Assignment(machine, resolve_table(table), reason)
        elif machine in from_specs:
            out[machine] = from_specs[machine]
    return out
