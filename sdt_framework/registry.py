"""The typed registry facade: the one object the rest of sdt-framework asks.

``build_registry()`` loads entry-point plugins, in-process plugins and TOML
sensor files; the orchestrator only calls ``registry.sensor(name)``,
``registry.classifiers()`` and the like and never touches ``pm.hook``. The
``register`` callback handed to every hook is the single place that validates
a spec, stamps its provenance and rejects duplicates.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any, TypeVar

import pluggy
from pydantic import ValidationError

from . import hookspecs
from .discovery import ENV_TRACE, LoadedPlugin, PluginInfo, discover
from .errors import DuplicateNameError, PluginLoadError, UnknownNameError
from .sensor_files import load_sensor_file, sensor_files_from_env
from .specs import ClassifierSpec, DatasetSpec, FeatureSetSpec, SensorSpec, Spec

__all__ = ["HOOKS", "Registry", "build_registry"]

S = TypeVar("S", bound=Spec)

#: hook name -> spec type it registers
HOOKS: dict[str, type[Spec]] = {
    "register_sensors": SensorSpec,
    "register_features": FeatureSetSpec,
    "register_classifiers": ClassifierSpec,
    "register_datasets": DatasetSpec,
}

IN_PROCESS = "(in-process)"


def _describe(spec: Spec) -> str:
    return f"plugin {spec.plugin!r} ({spec.distribution})"


class Registry:
    """Sensors, feature sets, classifiers and datasets by name."""

    def __init__(self, *, trace: bool = False) -> None:
        self._pm = pluggy.PluginManager(hookspecs.PROJECT)
        self._pm.add_hookspecs(hookspecs)
        self._items: dict[type[Spec], dict[str, Spec]] = {kind: {} for kind in HOOKS.values()}
        self._plugins: list[PluginInfo] = []
        self._conflicts: dict[tuple[type[Spec], str], DuplicateNameError] = {}
        self._trace = trace

    # -- registration -----------------------------------------------------------------
    def register_plugin(
        self,
        plugin: Any,
        name: str | None = None,
        *,
        distribution: str = IN_PROCESS,
        version: str = "",
    ) -> PluginInfo:
        """Register a plugin object or module and collect what its hooks provide.

        Hook implementations whose argument names are not in the spec are
        rejected by pluggy; a misspelled hook name is rejected here. A hook
        that raises marks the plugin ``error`` and registers nothing of it.
        """
        name = name or getattr(plugin, "__name__", None) or type(plugin).__name__
        info = PluginInfo(name, distribution, version, "loaded")
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
        if isinstance(spec, Mapping):
            try:
                spec = kind.model_validate(dict(spec))
            except ValidationError as exc:
                raise PluginLoadError(
                    info.name, info.distribution, f"invalid {kind.kind}: {exc}"
                ) from None
        if not isinstance(spec, kind):
            raise PluginLoadError(
                info.name,
                info.distribution,
                f"registered {type(spec).__name__}, expected {kind.__name__}",
            )
        staged.append(
            spec.model_copy(update={"plugin": info.name, "distribution": info.distribution})
        )

    def _commit(self, staged: list[Spec], info: PluginInfo) -> None:
        for spec in staged:
            table = self._items[type(spec)]
            existing = table.get(spec.name)
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

    def _collect(self, loaded: LoadedPlugin) -> PluginInfo:
        info = loaded.info
        try:
            self._pm.register(loaded.obj, name=f"{info.distribution}:{info.name}")
            self._pm.check_pending()
        except (ValueError, pluggy.PluginValidationError) as exc:
            self._fail(loaded, f"invalid hook implementation: {exc}")
            return info
        staged: list[Spec] = []
        for hook_name, kind in HOOKS.items():
            hook = getattr(self._pm.hook, hook_name)
            for impl in hook.get_hookimpls():
                if impl.plugin is not loaded.obj:
                    continue
                try:
                    impl.function(register=lambda spec, k=kind: self._stage(k, spec, info, staged))
                except PluginLoadError as exc:
                    self._fail(loaded, exc.reason)
                    return info
                except Exception as exc:
                    self._fail(loaded, f"{hook_name} raised {type(exc).__name__}: {exc}")
                    return info
        self._commit(staged, info)
        self._plugins.append(info)
        return info

    def _fail(self, loaded: LoadedPlugin, reason: str) -> None:
        if self._pm.is_registered(loaded.obj):
            self._pm.unregister(loaded.obj)
        loaded.info.status = "error"
        loaded.info.error = reason
        self._plugins.append(loaded.info)

    # -- lookup -----------------------------------------------------------------------
    def _get(self, kind: type[S], name: str) -> S:
        conflict = self._conflicts.get((kind, name))
        if conflict is not None:
            raise conflict
        try:
            return self._items[kind][name]  # type: ignore[return-value]
        except KeyError:
            raise UnknownNameError(kind.kind, name, self._items[kind]) from None

    def _all(self, kind: type[S]) -> list[S]:
        return [self._items[kind][key] for key in sorted(self._items[kind])]  # type: ignore[misc]

    def sensor(self, name: str) -> SensorSpec:
        """The sensor profile called ``name``."""
        return self._get(SensorSpec, name)

    def sensors(self) -> list[SensorSpec]:
        """All sensor profiles, sorted by name."""
        return self._all(SensorSpec)

    def feature_set(self, name: str) -> FeatureSetSpec:
        """The feature set called ``name``."""
        return self._get(FeatureSetSpec, name)

    def feature_sets(self) -> list[FeatureSetSpec]:
        """All feature sets, sorted by name."""
        return self._all(FeatureSetSpec)

    def classifier(self, name: str) -> ClassifierSpec:
        """The classifier called ``name``."""
        return self._get(ClassifierSpec, name)

    def classifiers(self) -> list[ClassifierSpec]:
        """All classifiers, sorted by name."""
        return self._all(ClassifierSpec)

    def dataset(self, name: str) -> DatasetSpec:
        """The dataset called ``name``."""
        return self._get(DatasetSpec, name)

    def datasets(self) -> list[DatasetSpec]:
        """All datasets, sorted by name."""
        return self._all(DatasetSpec)

    def plugins(self) -> list[PluginInfo]:
        """Every plugin seen, in discovery order, with its status."""
        return list(self._plugins)

    def problems(self) -> list[str]:
        """One line per plugin that failed or conflicted, for warnings."""
        return [
            f"plugin {p.name!r} ({p.distribution}): {p.error}"
            for p in self._plugins
            if p.status in {"error", "conflict"}
        ]

    def check(self) -> None:
        """Raise the first duplicate-name conflict, if any."""
        for error in self._conflicts.values():
            raise error


def build_registry(
    *,
    entry_points: bool = True,
    plugins: Iterable[Any] = (),
    sensor_files: Iterable[str | os.PathLike[str]] = (),
    environ: Mapping[str, str] | None = None,
) -> Registry:
    """Build a registry from installed entry points, extra plugins and sensor files.

    Parameters
    ----------
    entry_points
        Scan the ``sdt_framework`` entry-point group (False for isolated tests).
    plugins
        Extra plugin objects or modules registered in-process.
    sensor_files
        TOML sensor files, added after those named by ``SDT_SENSOR_PATH``.
    environ
        Environment for the ``SDT_*`` switches (default ``os.environ``).
    """
    environ = os.environ if environ is None else environ
    registry = Registry(trace=bool(environ.get(ENV_TRACE)))
    if entry_points:
        for found in discover(environ):
            if isinstance(found, LoadedPlugin):
                registry._collect(found)
            else:
                registry._plugins.append(found)
    for plugin in plugins:
        registry.register_plugin(plugin)
    for path in [*sensor_files_from_env(environ), *sensor_files]:
        registry.add_sensor_file(path)
    return registry
