"""Parts written as TOML files, one part per file, validated by :class:`PartSpec`.

A part file is data: its documents, its sourced values, its modes and its
price (``docs/sensors.md`` shows the format). Errors name the file, the field
path and the reason, as sensor files do.
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from pydantic import ValidationError

from ..errors import SpecFileError
from ..inputs import require_regular_file
from .model import PartSpec

__all__ = ["load_part_file", "load_part_text"]


def load_part_text(text: str, where: str | os.PathLike[str]) -> PartSpec:
    """Validate one part from TOML ``text``; ``where`` names it in errors."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SpecFileError(where, "", f"not valid TOML: {exc}") from None
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
    path = Path(path)
    require_regular_file(path, "part file")
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SpecFileError(path, "", "file not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SpecFileError(path, "", f"cannot read: {exc}") from None
    return load_part_text(text, path)
