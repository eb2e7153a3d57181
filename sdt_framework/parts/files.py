"""Parts written as TOML files, one part per file, validated by :class:`PartSpec`.

A part file is data: its documents, its sourced values, its modes and its
price (``docs/sensors.md`` shows the format). Errors name the file, the field
path and the reason, as sensor files do.
"""

from __future__ import annotations

import os
from functools import lru_cache
from typing import Any

from ..toml_files import parse_toml, read_toml, validate_file
from .model import PartSpec

__all__ = ["load_part_file", "load_part_text"]


@lru_cache(maxsize=256)
def load_part_text(text: str, where: str | os.PathLike[str]) -> PartSpec:
    """Validate one part from TOML ``text``; ``where`` names it in errors.

    Kept by text and name for the process: a part is frozen and its text validates to the
    same part every time, so a process that builds its registry again (a notebook, a sweep,
    the test suite) parses and validates each part of a catalogue once, not at every build
    (two thirds of a build's time). A text that fails is not kept.
    """
    return _validate(parse_toml(text, where), where)


def _validate(data: dict[str, Any], where: str | os.PathLike[str]) -> PartSpec:
    unknown = "unknown field (see the part format in docs/sensors.md)"
    return validate_file(PartSpec, data, where, unknown=unknown)


def load_part_file(path: str | os.PathLike[str]) -> PartSpec:
    """Read and validate the part in one TOML file."""
    return _validate(read_toml(path, what="part file"), path)
