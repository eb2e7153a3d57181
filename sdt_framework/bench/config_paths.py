"""Paths in the configuration files sdt writes: relative to the file's own folder.

A results folder is shared: zipped, attached to a thesis, moved to another
machine. Its ``config.toml`` (and an exploration's ``sweep.toml``) must not
carry the absolute path of the author's data, yet it must still resume the
folder. So sdt writes every path setting relative to the folder that holds the
file (``data = "../pump/manifest.csv"``), and reads a file it wrote (known by
its first line) back against that folder. A configuration a user wrote keeps
its own rule: relative paths are taken from the working directory, as given.
The identity a results folder is resumed by compares paths relative to the
folder (``bench.folder``), so a folder written before this rule (absolute
paths) still resumes, and a folder moved with its data resumes too.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

__all__ = [
    "PATH_SETTINGS",
    "WRITTEN_HEADERS",
    "relative_to",
    "resolve_written",
    "written_by_sdt",
]

#: Settings holding a file-system path.
PATH_SETTINGS = ("data", "allocation")  # cache_dir is not written (bench.config)
# and ``zones``: each value naming a zone-table file (``FILE.toml`` or ``FILE.toml#NAME``);
# ``machine_specs``: a machine file's path, or tables whose ``zone_table`` may name a file
#: First-line prefixes of the configuration files sdt writes.
WRITTEN_HEADERS = ("# Resolved by sdt benchmark", "# The sweep as run by sdt explore")


def written_by_sdt(path: str | os.PathLike[str]) -> bool:
    """Whether the file at ``path`` is a configuration sdt wrote (by its first line)."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(64).decode("utf-8", errors="replace")
    except OSError:
        return False
    return head.startswith(WRITTEN_HEADERS)


def _zone_files(settings: dict[str, Any], move: Any) -> dict[str, Any]:
    """``zones`` with ``move`` applied to each value naming a file (``FILE.toml[#NAME]``)."""
    zones = settings.get("zones")
    if not isinstance(zones, dict):
        return settings
    moved = {}
    for machine, spec in zones.items():
        path, sep, name = spec.partition("#") if isinstance(spec, str) else ("", "", "")
        moved[machine] = move(path) + sep + name if path.endswith(".toml") else spec
    return {**settings, "zones": moved}


def _machine_files(settings: dict[str, Any], move: Any) -> dict[str, Any]:
    """``machine_specs`` with ``move`` applied to its path, or to each table's zone-table file."""
    given = settings.get("machine_specs")
    if isinstance(given, str):
        return {**settings, "machine_specs": move(given)}
    if not isinstance(given, dict):
        return settings
    moved = {}
    for name, table in given.items():
        spec = table.get("zone_table") if isinstance(table, dict) else None
        path, sep, rest = spec.partition("#") if isinstance(spec, str) else ("", "", "")
        moved[name] = (
            {**table, "zone_table": move(path) + sep + rest} if path.endswith(".toml") else table
        )
    return {**settings, "machine_specs": moved}


def relative_to(settings: dict[str, Any], folder: str | os.PathLike[str]) -> dict[str, Any]:
    """``settings`` with every path setting written relative to ``folder``."""
    start = os.path.abspath(folder)

    def move(path: str) -> str:
        return Path(os.path.relpath(os.path.abspath(path), start)).as_posix()

    out = dict(settings)
    for name in PATH_SETTINGS:
        if isinstance(out.get(name), str):
            out[name] = move(out[name])
    return _machine_files(_zone_files(out, move), move)


def resolve_written(settings: dict[str, Any], folder: str | os.PathLike[str]) -> dict[str, Any]:
    """``settings`` read from a file sdt wrote in ``folder``: relative paths joined to it."""

    def move(path: str) -> str:
        if os.path.isabs(path):
            return path
        return os.path.normpath(os.path.join(os.path.abspath(folder), path))

    out = dict(settings)
    for name in PATH_SETTINGS:
        if isinstance(out.get(name), str):
            out[name] = move(out[name])
    return _machine_files(_zone_files(out, move), move)
