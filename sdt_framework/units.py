"""Acceleration units: standard gravity and the one table every module converts with.

Samples are carried in g (standard gravity, g_n) everywhere inside the
framework; a file, a manifest row, a pair or the command line may give them in
``g``, ``mg`` or ``m/s^2`` (:data:`UNITS`), and :data:`TO_G` turns each into g.
g_n itself is data with its source (``units.toml``, the 3rd CGPM's
declaration), read once here: a velocity in mm/s, a random walk in
(m/s)/sqrt(h) and a unit mix-up ratio all use this one value. The spellings a
DAQ file uses for those units (``m/s2``, ``m/s²``, ``gn``) map to them through
:func:`acceleration_units`.

This module is the bottom layer (it imports nothing of the framework), and no
other module spells g_n or a unit table (``tests/foundation/test_units.py``).
"""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from importlib import resources
from types import MappingProxyType
from typing import Literal

__all__ = [
    "G_N",
    "SPELLINGS",
    "TO_G",
    "UNITS",
    "Unit",
    "acceleration_units",
    "units_list",
]

_DATA = tomllib.loads(resources.files(__package__).joinpath("units.toml").read_text("utf-8"))

#: standard gravity g_n, m/s^2 (``units.toml``: the 3rd CGPM, 1901)
G_N: float = float(_DATA["standard_gravity"]["value"])

#: an acceleration unit a signal may be given in (the keys of :data:`TO_G`)
Unit = Literal["g", "mg", "m/s^2"]
#: multiply by this to get g: the SI prefix milli for mg, 1 / g_n for m/s^2
TO_G: Mapping[str, float] = MappingProxyType({"g": 1.0, "mg": 1e-3, "m/s^2": 1.0 / G_N})
#: the acceleration units, in the order messages list them
UNITS: tuple[str, ...] = tuple(TO_G)

#: the spellings of acceleration units found in DAQ files -> the name in :data:`UNITS`
SPELLINGS: Mapping[str, str] = MappingProxyType(
    {
        "g": "g",
        "gn": "g",
        "g0": "g",
        "mg": "mg",
        "m/s^2": "m/s^2",
        "m/s2": "m/s^2",
        "m/s²": "m/s^2",
        "m/s/s": "m/s^2",
        "m/sec^2": "m/s^2",
        "(m/s)/s": "m/s^2",
        "m s^-2": "m/s^2",
        "m*s^-2": "m/s^2",
    }
)


def acceleration_units(units: str | None) -> str | None:
    """The name in :data:`UNITS` (``g``, ``mg``, ``m/s^2``) for a unit string from a file,
    or None when it is not one of those (a voltage, a force, an empty label)."""
    if units is None:
        return None
    key = " ".join(units.strip().split()).lower().replace("**", "^")
    return SPELLINGS.get(key)


def units_list(last: str = ", ") -> str:
    """``g, mg, m/s^2`` (``last=" or "``: ``g, mg or m/s^2``): the units as a message lists
    them."""
    *head, tail = UNITS
    return f"{', '.join(head)}{last}{tail}"
