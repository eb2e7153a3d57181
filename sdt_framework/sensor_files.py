"""Sensor profiles written as TOML files: a sensor without code.

A file holds the :class:`~sdt_framework.specs.SensorSpec` fields at top level,
or one or more ``[[sensor]]`` tables. It goes through the same model as a
Python plugin; errors name the file, the field path and the reason.
"""

from __future__ import annotations

import os
import tomllib
from collections.abc import Iterator
from pathlib import Path

from pydantic import ValidationError

from .errors import SpecFileError
from .inputs import require_regular_file
from .specs import SensorSpec

__all__ = ["ENV_SENSOR_PATH", "load_sensor_file", "sensor_files_from_env"]

ENV_SENSOR_PATH = "SDT_SENSOR_PATH"


def load_sensor_file(path: str | os.PathLike[str]) -> list[SensorSpec]:
    """Read and validate every sensor profile in one TOML file."""
    path = Path(path)
    require_regular_file(path, "sensor file")
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise SpecFileError(path, "", "file not found; check the path") from None
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise SpecFileError(path, "", f"cannot read: {reason}; give a readable TOML file") from None
    except UnicodeDecodeError as exc:
        raise SpecFileError(
            path, "", f"not UTF-8 text (byte {exc.start}); save it as a UTF-8 TOML file"
        ) from None
    except tomllib.TOMLDecodeError as exc:
        raise SpecFileError(path, "", f"not valid TOML: {exc}") from None

    tables = data.get("sensor", [data])
    if isinstance(tables, dict):
        tables = [tables]
    specs = []
    for index, table in enumerate(tables):
        prefix = f"sensor[{index}]." if "sensor" in data else ""
        try:
            specs.append(SensorSpec.model_validate(table))
        except ValidationError as exc:
            first = exc.errors()[0]
            field = prefix + ".".join(str(part) for part in first["loc"])
            reason = first["msg"]
            if first.get("type") == "extra_forbidden":
                reason = "unknown field (check its spelling against `sdt sensors show adxl345`)"
            raise SpecFileError(path, field.rstrip("."), reason) from None
    return specs


def sensor_files_from_env(
    environ: os._Environ[str] | dict[str, str] | None = None,
) -> Iterator[Path]:
    """The ``*.toml`` files named by ``SDT_SENSOR_PATH`` (files or folders, os.pathsep)."""
    environ = os.environ if environ is None else environ
    for entry in filter(None, environ.get(ENV_SENSOR_PATH, "").split(os.pathsep)):
        path = Path(entry)
        if path.is_dir():
            yield from sorted(path.glob("*.toml"))
        else:
            yield path
