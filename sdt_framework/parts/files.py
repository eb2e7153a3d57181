"""Parts written as TOML files, one part per file, validated by :class:`PartSpec`.

A part file is data: its documents, its sourced values, its modes and its
price (``docs/sensors.md`` shows the format). Errors name the file, the field
path and the reason, as sensor files do.
"""

from __future__ import annotations

import os
from typing import Any

from pydantic import ValidationError

from ..errors import SpecFileError
from ..toml_files import parse_toml, read_toml
from .model import PartSpec

__all__ = ["load_part_file", "load_part_text"]


def load_part_text(text: str, where: str | os.PathLike[str]) -> PartSpec:
    """Validate one part from TOML ``text``; ``where`` names it in errors."""
    return _validate(parse_toml(text, where), where)


def _validate(data: dict[str, Any], where: str | os.PathLike[str]) -> PartSpec:
    try:
        return PartSpec.model_validate(data)
    except ValidationError as exc:
        first = exc.errors()[0]
        field = ".".join(str(part) for part in first["loc"])
        reason = first["msg"].removeprefix("Value error, ")
        if first.get("type") == "extra_forbidden":
            reason = "unknown field (see the part format in docs/sensors.md)"
        raise SpecFileError(where, field, reason) from None


def load_part_file(path: str | os.PathLike[str]) -> PartSpec:
    """Read and validate the part in one TOML file."""
    return _validate(read_toml(path, what="part file"), path)
