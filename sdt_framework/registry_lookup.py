"""Reading the registry: every spec by name, parts in a mode, stages bound.

:class:`RegistryLookup` holds the lookup half of
:class:`~sdt_framework.registry.Registry`; the registration half (plugins,
validation, provenance, duplicates) stays in :mod:`sdt_framework.registry`,
which fills the tables read here.
"""

from __future__ import annotations

from typing import TypeVar

from .discovery import PluginInfo
from .errors import DuplicateNameError, SDTError, UnknownNameError
from .parts import PartSpec, resolve, split_name
from .specs import ClassifierSpec, DatasetSpec, FeatureSetSpec, ReaderSpec, SensorSpec, Spec
from .stages.bind import bind_stages
from .stages.spec import StageSpec

__all__ = ["RegistryLookup"]

S = TypeVar("S", bound=Spec)


class RegistryLookup:
    """Lookup by name over the tables a :class:`~sdt_framework.registry.Registry` fills."""

    #: kind -> name -> registered spec
    _items: dict[type[Spec], dict[str, Spec]]
    #: (kind, name) -> the duplicate-name error raised when that name is asked for
    _conflicts: dict[tuple[type[Spec], str], DuplicateNameError]
    #: every plugin seen, in discovery order
    _plugins: list[PluginInfo]
    filter_note: str
    filter_warnings: list[str]

    def _get(self, kind: type[S], name: str) -> S:
        conflict = self._conflicts.get((kind, name))
        if conflict is not None:
            raise conflict
        try:
            return self._items[kind][name]  # type: ignore[return-value]
        except KeyError:
            raise UnknownNameError(
                kind.kind, name, self._items[kind], note=self.filter_note
            ) from None

    def _all(self, kind: type[S]) -> list[S]:
        return [self._items[kind][key] for key in sorted(self._items[kind])]  # type: ignore[misc]

    def sensor(self, name: str) -> SensorSpec:
        """The sensor profile called ``name``, or a part in a mode (``adxl355[range=8g]``).

        A part's sensor is named in canonical form: every mode key, sorted,
        defaults filled in (``adxl355`` -> ``adxl355[odr=4000,range=2g]``).
        """
        if name in self._items[SensorSpec] or (SensorSpec, name) in self._conflicts:
            return self.bind(self._get(SensorSpec, name))
        base, modes = split_name(name)
        if base in self._items[PartSpec] or (PartSpec, base) in self._conflicts:
            return self.bind(resolve(self.part(base), modes).sensor)
        note = self.filter_note
        if modes and base in self._items[SensorSpec]:
            raise UnknownNameError("part", base, self._items[PartSpec], note=note)
        known = [*self._items[SensorSpec], *self._items[PartSpec]]
        raise UnknownNameError("sensor", name, known, note=note)

    def sensors(self, *, bound: bool = True) -> list[SensorSpec]:
        """All sensor profiles, sorted by name (parts: :meth:`parts`), stages bound.

        A profile whose stages do not bind (a stage no installed plugin
        registers) is left out here and named by :meth:`problems`; asking for
        it by name raises the one-line error. ``bound=False`` returns every
        profile as registered, unbound (to bind against another registry's stages).
        """
        if not bound:
            return self._all(SensorSpec)
        return [spec for _, spec, _ in self._bound_sensors() if spec is not None]

    def _bound_sensors(self) -> list[tuple[SensorSpec, SensorSpec | None, str]]:
        """(profile, bound profile or None, why not) for every registered sensor."""
        out = []
        for sensor in self._all(SensorSpec):
            try:
                out.append((sensor, self.bind(sensor), ""))
            except SDTError as exc:
                out.append((sensor, None, str(exc)))
        return out

    def bind(self, sensor: SensorSpec) -> SensorSpec:
        """``sensor`` with its listed stages bound to the stages registered here.

        Unknown stage names and parameters a stage rejects are one-line errors.
        """
        return bind_stages(sensor, self._items[StageSpec])  # type: ignore[arg-type]

    def stage(self, name: str) -> StageSpec:
        """The chain stage called ``name``."""
        return self._get(StageSpec, name)

    def stages(self) -> list[StageSpec]:
        """All chain stages, sorted by name."""
        return self._all(StageSpec)

    def part(self, name: str) -> PartSpec:
        """The part called ``name`` (without a mode)."""
        return self._get(PartSpec, name)

    def parts(self) -> list[PartSpec]:
        """All parts, sorted by name."""
        return self._all(PartSpec)

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

    def signal_reader(self, name: str) -> ReaderSpec:
        """The signal file reader called ``name``."""
        return self._get(ReaderSpec, name)

    def signal_readers(self) -> list[ReaderSpec]:
        """All signal file readers, sorted by name."""
        return self._all(ReaderSpec)

    def plugins(self) -> list[PluginInfo]:
        """Every plugin seen, in discovery order, with its status."""
        return list(self._plugins)

    def problems(self) -> list[str]:
        """One line per plugin switch naming nothing installed, per plugin that failed or
        conflicted, and per invalid spec a plugin registered: the CLI prints them as warnings."""
        lines = list(self.filter_warnings)
        for p in self._plugins:
            head = f"plugin {p.name!r} ({p.distribution})"
            lines += [f"{head}: {reason}" for reason in p.rejected]
            if p.status == "conflict" or (p.status == "error" and not p.rejected):
                lines.append(f"{head}: {p.error}")
        for sensor, bound, why in self._bound_sensors():
            if bound is None:
                lines.append(f"sensor {sensor.name!r} ({sensor.plugin}) left out: {why}")
        return lines

    def check(self) -> None:
        """Raise the first duplicate-name conflict, if any."""
        for error in self._conflicts.values():
            raise error
