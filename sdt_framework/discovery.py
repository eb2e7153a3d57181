"""Plugin discovery in three phases: find entry points, select, load.

Entry points of the ``sdt_framework`` group are found and sorted by
(distribution, name) so discovery is deterministic; the environment switches
``SDT_PLUGINS`` (load only these) and ``SDT_BLOCK_PLUGINS`` (never load these)
select among them, matching a plugin's entry-point name or its distribution
name. A plugin that fails to import becomes a :class:`PluginInfo` with status
``error`` instead of crashing the program. An entry point may name a module, an instance, or a
class (instantiated without arguments: :func:`plugin_object`). A switch naming nothing installed
is reported (:func:`filter_warnings`), and an unknown name looked up while a
switch left plugins out says so (:func:`filter_note`).
"""

from __future__ import annotations

import importlib.metadata as md
import inspect
import os
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from .errors import one_line, validation_summary
from .hookspecs import PROJECT

__all__ = [
    "ENV_BLOCK",
    "ENV_ONLY",
    "ENV_TRACE",
    "LoadedPlugin",
    "PluginInfo",
    "discover",
    "filter_note",
    "filter_warnings",
    "load_entry_point",
    "plugin_object",
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
    status: str  # loaded | partial | blocked | not selected | error | conflict
    error: str = ""
    provides: dict[str, list[str]] = field(default_factory=dict)
    #: one line per spec the plugin registered that did not validate (not registered)
    rejected: list[str] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready view."""
        return {
            "name": self.name,
            "distribution": self.distribution,
            "version": self.version,
            "status": self.status,
            "error": self.error,
            "provides": self.provides,
            "rejected": self.rejected,
        }


@dataclass
class LoadedPlugin:
    """An imported plugin object together with its bookkeeping record."""

    obj: Any
    info: PluginInfo


def plugin_object(obj: Any) -> Any:
    """The object whose hooks are registered for ``obj``: a class is instantiated.

    A plugin may be a module, an instance, or a class. pluggy would register a
    class's functions unbound, so ``def register_sensors(self, register)`` would
    be called without ``self``; the class is instantiated with no arguments
    instead (hooks written as static methods work either way). A class that
    needs arguments raises a :class:`TypeError` saying to name an instance.
    """
    if not inspect.isclass(obj):
        return obj
    try:
        return obj()
    except TypeError as exc:
        raise TypeError(
            f"plugin class {obj.__qualname__} cannot be instantiated without arguments "
            f"({exc}); name a module or an instance of it instead"
        ) from None


def load_entry_point(value: str, name: str = "") -> Any:
    """Import ``value`` (``'package.module'`` or ``'package.module:attr'``) as discovery does.

    Returns the plugin object (:func:`plugin_object` of what it names), so
    :func:`sdt_framework.conformance.check_plugin` can check the exact form an
    entry point declares.
    """
    entry = md.EntryPoint(name=name or value, value=value, group=PROJECT)
    return plugin_object(entry.load())


def _norm(name: str) -> str:
    return re.sub(r"[-_.]+", "-", name).lower()


def _listed(environ: Mapping[str, str], key: str) -> list[str]:
    return [part.strip() for part in environ.get(key, "").split(",") if part.strip()]


def _names(environ: Mapping[str, str], key: str) -> set[str] | None:
    listed = _listed(environ, key)
    return {_norm(part) for part in listed} if listed else None


def _entry_points() -> list[tuple[md.EntryPoint, str, str]]:
    """Every ``sdt_framework`` entry point with its distribution's name and version.

    A distribution's metadata is parsed once, not once per entry point and field:
    ``Distribution.name`` and ``.version`` each parse the whole METADATA file again,
    which made discovery most of a command's start-up.
    """
    named: dict[int, tuple[str, str]] = {}
    unique: dict[tuple[str, str, str], tuple[md.EntryPoint, str, str]] = {}
    for ep in md.entry_points(group=PROJECT):
        if ep.dist is None:
            dist, version = "?", "?"
        else:
            if id(ep.dist) not in named:
                meta = ep.dist.metadata
                named[id(ep.dist)] = (meta["Name"], meta["Version"])
            dist, version = named[id(ep.dist)]
        unique.setdefault((_norm(dist), ep.name, ep.value), (ep, dist, version))
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
    for ep, dist, version in _entry_points():
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
            obj = plugin_object(ep.load())
        except Exception as exc:
            info.status = "error"
            info.error = f"import of {ep.value} failed: {validation_summary(exc)}"
            results.append(info)
            continue
        results.append(LoadedPlugin(obj, info))
    return results


def filter_warnings(environ: Mapping[str, str], found: Sequence[PluginInfo]) -> list[str]:
    """One line per switch that names plugins no installed entry point has.

    ``found`` is every plugin discovery saw (loaded or not). A misspelled name
    in ``SDT_PLUGINS`` would otherwise load nothing without a word, and one in
    ``SDT_BLOCK_PLUGINS`` would block nothing.
    """
    known = {_norm(p.name) for p in found} | {_norm(p.distribution) for p in found}
    installed = ", ".join(sorted({p.name for p in found})) or "(none)"
    lines = []
    for key in (ENV_ONLY, ENV_BLOCK):
        unknown = [name for name in _listed(environ, key) if _norm(name) not in known]
        if not unknown:
            continue
        effect = "nothing is blocked by them"
        if key == ENV_ONLY:
            matched = len(_listed(environ, key)) > len(unknown)
            effect = "only the other names are loaded" if matched else "no plugin is loaded"
        lines.append(
            f"{key}={one_line(environ[key], 80)!r}: no installed plugin or distribution is "
            f"called {', '.join(repr(one_line(n, 40)) for n in unknown)}, so {effect}; "
            f"installed plugins: {installed}"
        )
    return lines


def filter_note(environ: Mapping[str, str], found: Sequence[PluginInfo]) -> str:
    """A sentence saying which switch left which plugins out ('' when none did)."""
    left_out = [p.name for p in found if p.status in {"blocked", "not selected"}]
    if not left_out:
        return ""
    active = " and ".join(
        f"{key}={one_line(environ[key], 80)!r}"
        for key in (ENV_ONLY, ENV_BLOCK)
        if environ.get(key, "").strip()
    )
    shown = ", ".join(left_out[:8]) + (
        f" and {len(left_out) - 8} more" if len(left_out) > 8 else ""
    )
    return (
        f"A plugin filter is active ({active}) and left out: {shown}; "
        f"unset it or let through the plugin that provides this name."
    )
