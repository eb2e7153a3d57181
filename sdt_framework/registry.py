"""The typed registry facade: the one object the rest of sdt-framework asks.

``build_registry()`` loads entry-point plugins, in-process plugins and TOML sensor
files; the orchestrator only calls ``registry.sensor(name)``, ``registry.classifiers()``
and the like, never ``pm.hook``. The ``register`` callback handed to every hook is the
single place that validates a spec, stamps its provenance and rejects duplicates.

:func:`default_registry` is the one process-wide registry that registered
names (``degrade(x, fs, "adxl345")``) are resolved in (:mod:`sdt_framework.api`).
Importing this module changes nothing below it: a lower layer that needs the
registered readers or stages takes them as an argument
(``reader_for(file, registry.signal_readers())``, ``registry.bind(sensor)``).
"""

from __future__ import annotations

import functools
import os
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import pluggy
from pydantic import ValidationError

from . import hookspecs
from .discovery import (
    ENV_TRACE,
    LoadedPlugin,
    PluginInfo,
    discover,
    filter_note,
    filter_warnings,
    load_entry_point,
    plugin_object,
)
from .errors import DuplicateNameError, PluginLoadError, validation_summary
from .parts import PartSpec
from .registry_lookup import RegistryLookup
from .sensor_files import load_sensor_file, sensor_files_from_env
from .specs import (
    POINT_SUFFIX,
    ClassifierSpec,
    DatasetSpec,
    FeatureSetSpec,
    ReaderSpec,
    SensorSpec,
    Spec,
)
from .stages.spec import StageSpec

#: ``load_entry_point`` is re-exported for :mod:`.conformance`, which sits above the registry
__all__ = ["HOOKS", "Registry", "build_registry", "default_registry", "load_entry_point"]

#: hook name -> spec type it registers
HOOKS: dict[str, type[Spec]] = {
    "register_sensors": SensorSpec,
    "register_features": FeatureSetSpec,
    "register_classifiers": ClassifierSpec,
    "register_datasets": DatasetSpec,
    "register_parts": PartSpec,
    "register_stages": StageSpec,
    "register_signal_readers": ReaderSpec,
}
#: kinds that share one namespace: a part is used where a sensor is
_SAME_NAMES = {SensorSpec: PartSpec, PartSpec: SensorSpec}

IN_PROCESS = "(in-process)"


def _describe(spec: Spec) -> str:
    return f"plugin {spec.plugin!r} ({spec.distribution})"


class Registry(RegistryLookup):
    """Sensors, feature sets, classifiers and datasets by name."""

    def __init__(self, *, trace: bool = False) -> None:
        self._pm = pluggy.PluginManager(hookspecs.PROJECT)
        self._pm.add_hookspecs(hookspecs)
        self._items: dict[type[Spec], dict[str, Spec]] = {kind: {} for kind in HOOKS.values()}
        self._plugins: list[PluginInfo] = []
        self._conflicts: dict[tuple[type[Spec], str], DuplicateNameError] = {}
        self._trace = trace
        #: appended to unknown-name errors while SDT_PLUGINS / SDT_BLOCK_PLUGINS left plugins out
        self.filter_note = ""
        #: SDT_PLUGINS / SDT_BLOCK_PLUGINS entries that name nothing installed
        self.filter_warnings: list[str] = []

    # -- registration -----------------------------------------------------------------
    def register_plugin(
        self,
        plugin: Any,
        name: str | None = None,
        *,
        distribution: str = IN_PROCESS,
        version: str = "",
    ) -> PluginInfo:
        """Register a plugin module, object or class and collect what its hooks provide.

        A class is instantiated without arguments (:func:`discovery.plugin_object`),
        as it is when an entry point names it.

        Hook implementations whose argument names are not in the spec are
        rejected by pluggy; a misspelled hook name is rejected here. A hook
        that raises marks the plugin ``error`` and registers nothing of it. An
        invalid spec is one line in ``info.rejected`` and is not registered;
        the plugin's valid specs are (status ``partial``).
        """
        name = name or getattr(plugin, "__name__", None) or type(plugin).__name__
        info = PluginInfo(name, distribution, version, "loaded")
        try:
            plugin = plugin_object(plugin)
        except TypeError as exc:
            info.status, info.error = "error", str(exc)
            self._plugins.append(info)
            return info
        return self._collect(LoadedPlugin(plugin, info))

    def add(self, spec: Spec | Mapping[str, Any], kind: type[Spec] | None = None) -> Spec:
        """Register one spec directly (notebooks, tests)."""
        kind = kind or type(spec)
        if kind not in self._items:
            raise TypeError(f"cannot register {kind!r}; expected one of {list(self._items)}")
        info = PluginInfo(IN_PROCESS, IN_PROCESS, "", "loaded")
        staged: list[Spec] = []
        self._stage(kind, spec, info, staged)
        self._commit(staged, info)
        self._plugins.append(info)
        return staged[0]

    def add_sensor_file(self, path: str | os.PathLike[str]) -> list[SensorSpec]:
        """Register every sensor profile in a TOML file."""
        path = Path(path)
        info = PluginInfo(str(path), "(sensor file)", "", "loaded")
        staged: list[Spec] = []
        for spec in load_sensor_file(path):
            self._stage(SensorSpec, spec, info, staged)
        self._commit(staged, info)
        self._plugins.append(info)
        return staged  # type: ignore[return-value]

    def _stage(self, kind: type[Spec], spec: Any, info: PluginInfo, staged: list[Spec]) -> None:
        """Validate ``spec`` and stage it, or raise a one-line :class:`PluginLoadError`."""
        reason = self._offer(kind, spec, info, staged)
        if reason:
            raise PluginLoadError(info.name, info.distribution, reason)

    @staticmethod
    def _offer(kind: type[Spec], spec: Any, info: PluginInfo, staged: list[Spec]) -> str:
        """Stage a validated, stamped copy of ``spec``; return why it is invalid, or ''."""
        if isinstance(spec, Mapping):
            try:
                spec = kind.model_validate(dict(spec))
            except ValidationError as exc:
                name = " ".join(str(spec.get("name", "?")).split())[:60]
                return f"invalid {kind.kind} {name!r}: {validation_summary(exc)}"
        if not isinstance(spec, kind):
            return f"registered {type(spec).__name__}, expected {kind.__name__}"
        # a sweep point keeps its base part's mode: 'adxl355[range=8g]~rate=2000'
        if "[" in spec.name and not POINT_SUFFIX.search(spec.name):
            return f"{spec.name!r}: brackets are reserved for part modes"
        staged.append(
            spec.model_copy(update={"plugin": info.name, "distribution": info.distribution})
        )
        return ""

    def _commit(self, staged: list[Spec], info: PluginInfo) -> None:
        for spec in staged:
            table = self._items[type(spec)]
            existing = self._existing(spec)
            if existing is not None:
                error = DuplicateNameError(
                    spec.kind, spec.name, _describe(existing), _describe(spec)
                )
                self._conflicts[(type(spec), spec.name)] = error
                info.status = "conflict"
                info.error = str(error)
                continue
            table[spec.name] = spec
            info.provides.setdefault(spec.kind, []).append(spec.name)
            if self._trace:
                print(f"sdt: {info.name} registered {spec.kind} {spec.name!r}", file=sys.stderr)

    def _existing(self, spec: Spec) -> Spec | None:
        """A spec already registered under ``spec``'s name in its namespace."""
        for kind in (type(spec), _SAME_NAMES.get(type(spec))):
            if kind is not None and spec.name in self._items[kind]:
                return self._items[kind][spec.name]
        return None

    def _collect(self, loaded: LoadedPlugin) -> PluginInfo:
        info = loaded.info
        try:
            self._pm.register(loaded.obj, name=f"{info.distribution}:{info.name}")
            self._pm.check_pending()
        except (ValueError, pluggy.PluginValidationError) as exc:
            self._fail(loaded, f"invalid hook implementation: {exc}")
            return info
        staged: list[Spec] = []

        def offer(spec: Any, kind: type[Spec]) -> None:
            reason = self._offer(kind, spec, info, staged)
            if reason:
                info.rejected.append(f"{reason}; not registered, the plugin's other specs are kept")

        for hook_name, kind in HOOKS.items():
            hook = getattr(self._pm.hook, hook_name)
            for impl in hook.get_hookimpls():
                if impl.plugin is not loaded.obj:
                    continue
                try:
                    impl.function(register=lambda spec, k=kind: offer(spec, k))
                except ValidationError as exc:  # the plugin built an invalid spec itself
                    info.rejected.append(
                        f"{hook_name} built an invalid {exc.title}: {validation_summary(exc)}; "
                        f"the hook stopped there, specs it registered before are kept"
                    )
                except Exception as exc:
                    self._fail(loaded, f"{hook_name} raised {validation_summary(exc)}")
                    return info
        if info.rejected:
            info.status = "partial" if staged else "error"
            info.error = "; ".join(info.rejected)
        self._commit(staged, info)
        self._plugins.append(info)
        return info

    def _fail(self, loaded: LoadedPlugin, reason: str) -> None:
        if self._pm.is_registered(loaded.obj):
            self._pm.unregister(loaded.obj)
        loaded.info.status = "error"
        loaded.info.error = reason
        self._plugins.append(loaded.info)


def build_registry(
    *,
    entry_points: bool = True,
    plugins: Iterable[Any] = (),
    sensor_files: Iterable[str | os.PathLike[str]] = (),
    environ: Mapping[str, str] | None = None,
) -> Registry:
    """Build a registry from installed entry points, extra plugins and sensor files.

    ``entry_points``: scan the ``sdt_framework`` entry-point group (False for isolated
    tests); ``plugins``: objects or modules registered in-process; ``sensor_files``: TOML
    sensor files, added after those named by ``SDT_SENSOR_PATH``; ``environ``: the
    ``SDT_*`` switches (default ``os.environ``).
    """
    environ = os.environ if environ is None else environ
    registry = Registry(trace=bool(environ.get(ENV_TRACE)))
    if entry_points:
        found = discover(environ)
        infos = [item.info if isinstance(item, LoadedPlugin) else item for item in found]
        registry.filter_warnings = filter_warnings(environ, infos)
        registry.filter_note = filter_note(environ, infos)
        for item in found:
            if isinstance(item, LoadedPlugin):
                registry._collect(item)
            else:
                registry._plugins.append(item)
    for plugin in plugins:
        registry.register_plugin(plugin)
    for path in [*sensor_files_from_env(environ), *sensor_files]:
        registry.add_sensor_file(path)
    return registry


@functools.cache
def default_registry() -> Registry:
    """The registry names are resolved in, built on first use and then reused.

    Built from the entry points, ``SDT_SENSOR_PATH`` and the ``SDT_*``
    switches of the environment at that moment. Call
    ``default_registry.cache_clear()`` to rebuild it (after installing a
    plugin or changing ``SDT_PLUGINS`` in a running session).
    """
    return build_registry()
