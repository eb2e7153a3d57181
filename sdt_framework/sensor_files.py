"""Sensor profiles written as TOML files: a sensor without code.

A file holds the :class:`~sdt_framework.specs.SensorSpec` fields at top level,
or one or more ``[[sensor]]`` tables. It goes through the same model as a
Python plugin; errors name the file, the field path and the reason.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

from .errors import SpecFileError, one_line
from .specs import SensorSpec
from .toml_files import read_toml, validate_file

__all__ = ["ENV_SENSOR_PATH", "load_sensor_file", "sensor_files_from_env"]

ENV_SENSOR_PATH = "SDT_SENSOR_PATH"
_UNKNOWN = "unknown field (check its spelling against `sdt sensors show adxl345`)"


def load_sensor_file(path: str | os.PathLike[str]) -> list[SensorSpec]:
    """Read and validate every sensor profile in one TOML file."""
    path = Path(path)
    data = read_toml(path, what="sensor file")
    tables = data.get("sensor", [data])
    if isinstance(tables, dict):
        tables = [tables]
    if not isinstance(tables, list):
        raise SpecFileError(
            path,
            "sensor",
            f"must be a table [sensor] or tables [[sensor]] of profile fields, got "
            f"{type(tables).__name__} {one_line(repr(tables), 60)}",
        )
    specs = []
    for index, table in enumerate(tables):
        prefix = f"sensor[{index}]." if "sensor" in data else ""
        specs.append(validate_file(SensorSpec, table, path, prefix=prefix, unknown=_UNKNOWN))
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
