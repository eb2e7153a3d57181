"""Zone tables as data: ISO severity boundaries in user-editable TOML files, validated.

A zone table is three boundaries of broad-band r.m.s. velocity (A/B, B/C,
C/D in mm/s) over the band ISO grades it in: 10-1000 Hz, or 2-1000 Hz for
machines below 600 r/min (ISO 10816-3:2009 Annex A), with the document,
edition and table they come from. The tables shipped with the package are
``iso10816-3.toml`` and ``iso20816-1.toml`` next to this module (sources in
their comments and in docs/severity.md); a plant's own alarm limits are a
file of the same form, given by path. A file holds one or more ``[[table]]``
entries; ``FILE.toml#name`` picks one of several.

Every fault in a table (boundaries not increasing, an unknown machine group,
a unit other than mm/s, a band ISO does not grade in, a boundary written as a
boolean or a string: ``b_c = true`` is not 1 mm/s, ``"1.0"`` is text) is one
:class:`SpecFileError` line. A 2-1000 Hz table is a valid table, but the
windows' V_RMS feature is 10-1000 Hz: :func:`assign_tables` refuses to grade
windows by it, with the reason (:func:`band_problem`).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Literal

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from ..errors import SDTError, SpecFileError
from ..toml_files import parse_toml, read_toml, validate_file

__all__ = [
    "BUILTIN_FILES",
    "ISO_BANDS_HZ",
    "MACHINE_GROUPS",
    "V_RMS_BAND_HZ",
    "ZONES",
    "Assignment",
    "ZoneTable",
    "band_problem",
    "builtin_tables",
    "grade",
    "load_zone_file",
    "resolve_table",
]

ZONES = ("A", "B", "C", "D")
MACHINE_GROUPS = ("group 1", "group 2", "typical", "plant", "pump category I", "pump category II")
BUILTIN_FILES = ("iso10816-3.toml", "iso20816-1.toml")
#: the band of the V_RMS feature the tables grade (plugins/features/paper8.py)
V_RMS_BAND_HZ = (10.0, 1000.0)
#: the band ISO 10816-3:2009 Annex A grades machines below 600 r/min in
LOW_SPEED_BAND_HZ = (2.0, 1000.0)
ISO_BANDS_HZ = (V_RMS_BAND_HZ, LOW_SPEED_BAND_HZ)


def _number(value: object) -> object:
    """``value`` if it is a TOML number (integer or float); a boolean or a string is refused,
    where pydantic's lax mode would read ``true`` as 1 and ``"1.0"`` as 1.0."""
    if isinstance(value, bool):
        raise ValueError(f"must be a number, got the boolean {str(value).lower()}")
    if isinstance(value, str):
        raise ValueError(f"must be a number, got the string {value!r}: drop the quotes")
    if not isinstance(value, int | float):
        raise ValueError(f"must be a number, got {type(value).__name__} {value!r}")
    return value


class Boundaries(BaseModel):
    """The A/B, B/C and C/D boundaries, strictly increasing, in the table's unit."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    a_b: float = Field(gt=0, allow_inf_nan=False)
    b_c: float = Field(gt=0, allow_inf_nan=False)
    c_d: float = Field(gt=0, allow_inf_nan=False)

    _numbers = field_validator("a_b", "b_c", "c_d", mode="before")(_number)

    @model_validator(mode="after")
    def _increasing(self) -> Boundaries:
        if not self.a_b < self.b_c < self.c_d:
            raise ValueError(
                f"boundaries must increase a_b < b_c < c_d (zone A below zone B below C), got "
                f"{self.a_b:g}, {self.b_c:g}, {self.c_d:g}"
            )
        return self


class ZoneTable(BaseModel):
    """One zone table: its boundaries and where they come from."""

    model_config = ConfigDict(extra="forbid", frozen=True)

    name: str = Field(min_length=1, pattern=r"^[A-Za-z0-9][A-Za-z0-9._-]*$")
    title: str = Field(min_length=1)
    machine_group: str
    support: Literal["rigid", "flexible", "any"] = "any"
    unit: str
    band_hz: tuple[float, float] = V_RMS_BAND_HZ
    document: str = Field(min_length=1)
    edition: str = Field(min_length=1)
    table_ref: str = Field(min_length=1)
    boundaries: Boundaries

    @field_validator("machine_group")
    @classmethod
    def _group(cls, value: str) -> str:
        if value not in MACHINE_GROUPS:
            raise ValueError(
                f"unknown machine group {value!r}; use one of {', '.join(MACHINE_GROUPS)} "
                f"('plant' for your own limits)"
            )
        return value

    @field_validator("unit")
    @classmethod
    def _unit(cls, value: str) -> str:
        if value != "mm/s":
            raise ValueError(
                f"unit {value!r} is not mm/s: the tables grade V_RMS in mm/s; convert the "
                f'boundaries (1 in/s = 25.4 mm/s) and write unit = "mm/s"'
            )
        return value

    @field_validator("band_hz", mode="before")
    @classmethod
    def _band_numbers(cls, value: object) -> object:
        if isinstance(value, list | tuple):
            for item in value:
                _number(item)
        return value

    @field_validator("band_hz")
    @classmethod
    def _band(cls, value: tuple[float, float]) -> tuple[float, float]:
        if tuple(map(float, value)) not in ISO_BANDS_HZ:
            raise ValueError(
                f"band {list(value)} Hz is not a band ISO grades V_RMS in; write band_hz = "
                f"[10.0, 1000.0], or [2.0, 1000.0] for a machine below 600 r/min "
                f"(ISO 10816-3:2009 Annex A)"
            )
        return value

    @property
    def band_text(self) -> str:
        """The table's band, "10-1000 Hz"."""
        return f"{self.band_hz[0]:g}-{self.band_hz[1]:g} Hz"

    @property
    def cuts(self) -> np.ndarray:
        """The three boundaries as an array, for :func:`grade`."""
        b = self.boundaries
        return np.array([b.a_b, b.b_c, b.c_d])

    @property
    def source(self) -> str:
        """Document, edition and table, as a citation."""
        return f"{self.document}:{self.edition}, {self.table_ref}"


class _ZoneFile(BaseModel):
    model_config = ConfigDict(extra="forbid")

    table: list[ZoneTable] = Field(min_length=1)


def band_problem(table: ZoneTable, window_s: float | None = None) -> str | None:
    """Why the windows' V_RMS (10-1000 Hz) cannot be graded by ``table``; None if it can.

    A 2-1000 Hz table grades a value the features do not hold: their V_RMS is
    10-1000 Hz (paper8), and a 2 Hz low edge needs 4 lines below it, so
    windows of at least 2 s (the features' windows are 0.64 s by default).
    Grading a 10-1000 Hz value against it would read low without saying so.
    """
    if tuple(map(float, table.band_hz)) == V_RMS_BAND_HZ:
        return None
    windows = f" over {window_s:g} s windows" if window_s else ""
    need = 4 / table.band_hz[0]
    return (
        f"zone table {table.name!r} grades V_RMS over {table.band_text} (machines below 600 "
        f"r/min); the features' V_RMS is 10-1000 Hz{windows}, and a {table.band_hz[0]:g} Hz "
        f"edge needs windows of at least {need:g} s: grade the windows with a 10-1000 Hz "
        f"table, or read the {table.band_text} overall off a whole recording "
        f"(severity.velocity_spectrum(x, fs, band=({table.band_hz[0]:g}, "
        f"{table.band_hz[1]:g})).overall)"
    )


def grade(v_rms: np.ndarray, table: ZoneTable) -> np.ndarray:
    """Zone index 0-3 (A-D) of each velocity; a value on a boundary is in the lower zone."""
    return np.searchsorted(table.cuts, np.asarray(v_rms, dtype=float), side="left")


def _validated(data: dict, where: str | os.PathLike[str]) -> list[ZoneTable]:
    tables = validate_file(_ZoneFile, data, where, unknown="unknown field (see docs/severity.md)")
    names = [t.name for t in tables.table]
    doubled = sorted({n for n in names if names.count(n) > 1})
    if doubled:
        raise SpecFileError(where, "table", f"table name(s) {doubled} given twice")
    return tables.table


def load_zone_file(path: str | os.PathLike[str]) -> list[ZoneTable]:
    """Every table of the zone-table file at ``path``."""
    return _validated(read_toml(path, what="zone table file"), path)


def builtin_tables() -> dict[str, ZoneTable]:
    """The tables shipped with sdt, by name."""
    out: dict[str, ZoneTable] = {}
    for name in BUILTIN_FILES:
        text = resources.files(__package__).joinpath(name).read_text(encoding="utf-8")
        out.update({t.name: t for t in _validated(parse_toml(text, name), name)})
    return out


def resolve_table(spec: str) -> ZoneTable:
    """A table by built-in name, by ``FILE.toml`` (one table) or ``FILE.toml#name``."""
    path, _, name = spec.partition("#")
    if path.endswith(".toml") or Path(path).exists():
        tables = load_zone_file(path)
        if name:
            found = [t for t in tables if t.name == name]
            if not found:
                raise SpecFileError(path, "", f"no table named {name!r}; it holds {_names(tables)}")
            return found[0]
        if len(tables) > 1:
            raise SpecFileError(
                path, "", f"holds {len(tables)} tables; pick one as {path}#NAME ({_names(tables)})"
            )
        return tables[0]
    known = builtin_tables()
    if spec not in known:
        raise SDTError(
            f"unknown zone table {spec!r}; give a built-in name ({', '.join(known)}) or a "
            f"path to a .toml zone table file"
        )
    return known[spec]


def _names(tables: list[ZoneTable]) -> str:
    return ", ".join(t.name for t in tables)


@dataclass(frozen=True)
class Assignment:
    """The table that grades one machine, and why it was chosen (:mod:`.assign`)."""

    machine: str
    table: ZoneTable
    reason: str
