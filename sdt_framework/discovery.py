"""Plugin discovery in three phases: find entry points, select, load.

Entry points of the ``sdt_framework`` group are found and sorted by
(distribution, name) so discovery is deterministic; the environment switches
``SDT_PLUGINS`` (load only these) and ``SDT_BLOCK_PLUGINS`` (never load these)
select among them, matching a plugin's entry-point name or its distribution
name. A plugin that fails to import becomes a :class:`PluginInfo` with status
``error`` instead of crashing the program.
"""

from __future__ import annotations

import importlib.metadata as md
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from .hookspecs import PROJECT

__all__ = [
    "ENV_BLOCK",
    "ENV_ONLY",
    "ENV_TRACE",
    "LoadedPlugin",
    "PluginInfo",
    "discover",
]

ENV_ONLY = "SDT_PLUGINS"
ENV_BLOCK = "SDT_BLOCK_PLUGINS"
ENV_TRACE = "SDT_TRACE_HOOKS"


@dataclass
class PluginInfo:
    """What ``sdt plugins list`` shows about one plugin."""

    name: str
    distribution: str
    version: str
    status: str  # loaded | blocked | not selected | error | conflict
    error: str = ""
    provides: dict[str, list[str]] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready view."""
        return {
            "name": self.name,
            "distribution": self.distribution,
            "version": self.version,
            "status": self.status,
            "error": self.error,
            "provides": self.provides,
        }


@dataclass
class LoadedPlugin:
    """An imported plugin object together with its bookkeeping record."""

    obj: Any
    info: PluginInfo


def _norm(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def _names(environ: Mapping[str, str], key: str) -> set[str] | None:
    raw = environ.get(key)
    if raw is None or not raw.strip():
        return None
    return {_norm(part) for part in raw.split(",") if part.strip()}


def _entry_points() -> list[md.EntryPoint]:
    unique: dict[tuple[str, str, str], md.EntryPoint] = {}
    for ep in md.entry_points(group=PROJECT):
        dist = ep.dist.name if ep.dist else "?"
        unique.setdefault((_norm(dist), ep.name, ep.value), ep)
    return [unique[key] for key in sorted(unique)]


def discover(environ: Mapping[str, str] | None = None) -> list[LoadedPlugin | PluginInfo]:
    """Find, select and load every ``sdt_framework`` entry point.

    Returns a :class:`LoadedPlugin` for each imported plugin and a bare
    :class:`PluginInfo` for each one that was blocked, not selected or failed.
    """
    environ = os.environ if environ is None else environ
    only = _names(environ, ENV_ONLY)
    blocked = _names(environ, ENV_BLOCK) or set()
    results: list[LoadedPlugin | PluginInfo] = []
    for ep in _entry_points():
        dist = ep.dist.name if ep.dist else "?"
        version = ep.dist.version if ep.dist else "?"
        info = PluginInfo(ep.name, dist, version, "loaded")
        keys = {_norm(ep.name), _norm(dist)}
        if keys & blocked:
            info.status = "blocked"
            results.append(info)
            continue
        if only is not None and not keys & only:
            info.status = "not selected"
            results.append(info)
            continue
        try:
            obj = ep.load()
        except Exception as exc:
            info.status = "error"
            info.error = f"import of {ep.value} failed: {type(exc).__name__}: {exc}"
            results.append(info)
            continue
        results.append(LoadedPlugin(obj, info))
    return results
