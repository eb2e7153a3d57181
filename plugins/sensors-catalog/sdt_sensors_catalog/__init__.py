"""sdt-sensors-catalog: real accelerometers from their datasheets, as sdt-framework parts.

Each part is one TOML file in ``parts/`` (shipped as package data): its
documents, every chain value with the table or page it comes from, its
operating modes and an indicative price. This module only reads those files
and registers them through the ``register_parts`` hook; sdt-framework validates
them. The distribution is found through its ``sdt_framework`` entry point,
like any third-party plugin.
"""

from __future__ import annotations

from importlib import resources
from importlib.resources.abc import Traversable

from sdt_framework import hookimpl
from sdt_framework.parts import PartSpec, load_part_text

__version__ = "0.1.0"


def part_files() -> list[Traversable]:
    """The part files shipped with this distribution, sorted by name."""
    folder = resources.files(__name__) / "parts"
    return sorted((f for f in folder.iterdir() if f.name.endswith(".toml")), key=lambda f: f.name)


def load_parts() -> list[PartSpec]:
    """Every part of the catalogue, validated."""
    return [
        load_part_text(f.read_text(encoding="utf-8"), f"{__name__}/parts/{f.name}")
        for f in part_files()
    ]


@hookimpl
def register_parts(register):
    """Register every part of the catalogue."""
    for part in load_parts():
        register(part)
