"""Which zone table grades which machine: the defaults for the pump datasets, a config, --zones.

The defaults name, beside the table, why it was chosen; the pump end of both
default machines is graded by the motor's table as a proxy (:data:`PUMP_PROXY`).
A table whose band is not the windows' V_RMS band (a 2-1000 Hz table) is
refused here, before any run, with the reason (:func:`.tables.band_problem`).
"""

from __future__ import annotations

from collections.abc import Mapping

from ..errors import SDTError
from .tables import Assignment, ZoneTable, band_problem, builtin_tables, resolve_table

__all__ = ["DEFAULT_TABLES", "PUMP_PROXY", "Assignment", "assign_tables"]

#: why the pump end (ch4, ch5) of the default machines is graded by the motor's table
PUMP_PROXY = (
    "the pump end (ch4, ch5) is graded by the same table as a proxy: rotodynamic pumps are "
    "the subject of ISO 10816-7, whose boundaries no source read here gives"
)

#: which table grades which machine of the two pump datasets, and why
DEFAULT_TABLES: dict[str, tuple[str, str]] = {
    "Motor-2": (
        "iso20816-1-typical-low",
        "11 kW 4-pole set: below ISO 10816-3's 15 kW, so ISO 20816-1's typical ranges at "
        f"their low end, where Table C.1 puts motors up to 15 kW; {PUMP_PROXY}",
    ),
    "Motor-4": (
        "iso10816-3-group2-rigid",
        "22 kW 2-pole set: ISO 10816-3 group 2 (15-300 kW); rigid, the stricter support "
        f"class, as no source gives the rig's support natural frequency; {PUMP_PROXY}",
    ),
}


def _gradable(table: ZoneTable, where: str, window_s: float | None) -> ZoneTable:
    problem = band_problem(table, window_s)
    if problem:
        raise SDTError(f"{where}: {problem}")
    return table


def assign_tables(
    machines: list[str],
    choices: list[str] = (),
    configured: Mapping[str, str] | None = None,
    where: str = "[benchmark] zones",
    window_s: float | None = None,
) -> dict[str, Assignment]:
    """The table for each machine: ``choices`` ("TABLE" or "MACHINE=TABLE", ``--zones``),
    else ``configured`` (the benchmark config's ``zones``, MACHINE -> TABLE), else the default.

    A machine with none of them (a user's dataset) gets no table and is left
    out of the severity figures; the caller says so. A configured machine that
    is not in ``machines``, a table that does not resolve or one that cannot
    grade the windows' V_RMS (its band) is one line naming ``where`` (the
    config file) and the field; ``window_s`` (the windows' length) goes into
    that line.
    """
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
        elif machine in DEFAULT_TABLES:
            name, reason = DEFAULT_TABLES[machine]
            out[machine] = Assignment(machine, builtin_tables()[name], reason)
    return out
