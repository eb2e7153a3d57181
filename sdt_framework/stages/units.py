"""Physical units of a sensor drawn from its profile's tolerances (a per-unit Monte Carlo).

Unit ``k`` of a sensor draws each toleranced parameter from
``rng(seed, "unit", base_name, k, parameter)``: the same unit in every run
with the same base seed, whatever the other sensors, repetitions or
recordings, and whichever mode of a part is selected (``base_name`` drops the
mode and design-point suffixes). Each parameter has its own stream, so adding
a tolerance to one parameter leaves the others' draws as they were.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pydantic import ValidationError

from ..errors import SDTError, UnknownNameError, validation_summary
from ..seeding import rng
from ..specs import MODE_SUFFIX, POINT_SUFFIX, SensorSpec
from ..specs.stage_use import StageUse, Tolerance
from .spec import StageSpec

__all__ = ["base_name", "draw", "draw_unit", "drawn_stages", "has_tolerances"]

#: a normal draw is truncated at this many standard deviations
TRUNCATE_SD = 3.0


def base_name(name: str) -> str:
    """The sensor's name without a part's mode or a design point's settings."""
    return MODE_SUFFIX.sub("", POINT_SUFFIX.sub("", name))


def draw(tolerance: Tolerance, nominal: float, seed: int, *components: object) -> float:
    """One draw of a parameter: nominal + half-width x (truncated normal or uniform)."""
    gen = rng(seed, *components)
    if tolerance.distribution == "uniform":
        unit = gen.uniform(-1.0, 1.0)
    else:
        unit = gen.standard_normal()
        while abs(unit) > TRUNCATE_SD:
            unit = gen.standard_normal()
    return float(nominal + tolerance.half_width(nominal) * unit)


def has_tolerances(sensor: SensorSpec) -> bool:
    """Whether any field or listed stage of ``sensor`` has a tolerance."""
    return bool(sensor.tolerances) or any(use.tolerances for use in sensor.stages)


def _draw_axes(
    tolerance: Tolerance, use: StageUse | None, param: str, nominal: float, *where: object
) -> dict[str, dict[str, float]]:
    """A stage parameter's own draws on the Y and Z axes its tolerance lists (``per_axis``)."""
    values: dict[str, dict[str, float]] = {}
    for axis in sorted(tolerance.per_axis or {}):
        own = ((use.per_axis or {}) if use is not None else {}).get(axis, {})  # type: ignore[call-overload]
        value = draw(tolerance.on_axis(axis), float(own.get(param, nominal)), *where, axis)
        values.setdefault(axis, {})[param] = value
    return values


def _merge(into: dict[str, dict[str, float]], more: dict[str, dict[str, float]]) -> None:
    for axis, values in more.items():
        into.setdefault(axis, {}).update(values)


def drawn_stages(sensor: SensorSpec) -> list[str]:
    """Names of the stages ``sensor``'s tolerances name (``"stage.parameter"``), sorted."""
    return sorted({key.partition(".")[0] for key in sensor.tolerances if "." in key})


def _added(name: str, params: dict[str, float], per_axis: Any, stages: Mapping | None) -> StageUse:
    """A stage a tolerance adds to a unit, bound to its spec in ``stages`` when given."""
    if stages is None:
        return StageUse(name=name, params=params, per_axis=per_axis)
    if name not in stages:
        raise UnknownNameError("stage", name, stages, note="(named by a tolerance)")
    return StageUse(name=name, params=params, per_axis=per_axis, spec=stages[name])


def draw_unit(
    sensor: SensorSpec, seed: int, k: int, stages: Mapping[str, StageSpec] | None = None
) -> SensorSpec:
    """Unit ``k`` of ``sensor``: every toleranced value drawn, tolerances dropped.

    A tolerance ``"stage.parameter"`` applies to the listed stage of that
    name, or adds the stage (nominal value 0) to the unit when the profile
    does not list it: a profile's nominal chain stays as it is. An added stage
    is bound to its spec in ``stages`` (name -> spec, e.g. the registry's
    stages the benchmark's job carries), so the unit's chain needs no registry
    in the process that runs it (a worker process imports none); without
    ``stages`` it is bound when its chain is compiled. A tolerance
    with ``per_axis`` spreads draws the Y and Z values of the parameter on
    their own streams (the stage's ``per_axis``).

    A sensor without tolerances is returned as it is (every unit is nominal).
    A drawn value the model refuses (a negative noise density) is a one-line
    :class:`~sdt_framework.errors.SDTError` asking for a smaller spread.
    """
    if not has_tolerances(sensor):
        return sensor
    base = base_name(sensor.name)
    update: dict[str, Any] = {"tolerances": {}}
    added: dict[str, dict[str, float]] = {}
    added_axes: dict[str, dict[str, dict[str, float]]] = {}
    for key in sorted(sensor.tolerances):
        stage, _, param = key.partition(".")
        tolerance = sensor.tolerances[key]
        if param:  # a stage's parameter: on the listed stage, or on one added to the unit
            listed = [use for use in sensor.stages if use.name == stage]
            use = listed[0] if listed else None
            nominal = float(use.params.get(param, 0.0)) if use is not None else 0.0
            where = (seed, "unit", base, k, key)
            added.setdefault(stage, {})[param] = draw(tolerance, nominal, *where)
            _merge(
                added_axes.setdefault(stage, {}), _draw_axes(tolerance, use, param, nominal, *where)
            )
            continue
        nominal = float(getattr(sensor, key))
        update[key] = draw(tolerance, nominal, seed, "unit", base, k, key)
    uses = []
    for i, use in enumerate(sensor.stages):
        params = dict(use.params)
        axes = {axis: dict(values) for axis, values in (use.per_axis or {}).items()}
        for key in sorted(use.tolerances):
            where = (seed, "unit", base, k, f"{use.name}.{i}.{key}")
            nominal = float(params[key])
            params[key] = draw(use.tolerances[key], nominal, *where)
            _merge(axes, _draw_axes(use.tolerances[key], use, key, nominal, *where))
        params.update(added.pop(use.name, {}))
        _merge(axes, added_axes.pop(use.name, {}))
        uses.append(
            use.model_copy(update={"params": params, "tolerances": {}, "per_axis": axes or None})
        )
    uses += [
        _added(name, params, added_axes.get(name) or None, stages)
        for name, params in sorted(added.items())
    ]
    update["stages"] = tuple(uses)
    data = {**sensor.model_dump(), **update}
    try:
        unit = SensorSpec.model_validate({**data, "stages": ()})
    except ValidationError as exc:
        raise SDTError(
            f"sensor {sensor.name!r}, unit {k}: a drawn value is out of range "
            f"({validation_summary(exc)}); lower its tolerance's spread"
        ) from None
    unit = unit.model_copy(update={"stages": tuple(uses)})
    if any(use.spec is None for use in unit.stages):
        return unit  # bound (and checked) when its chain is compiled
    for use in unit.stages:
        for axis in ("x", *sorted(use.per_axis or {})):
            try:
                use.spec.params.model_validate(use.for_axis(axis).params)
            except ValidationError as exc:
                raise SDTError(
                    f"sensor {sensor.name!r}, unit {k}, stage {use.name!r}: a drawn value is "
                    f"out of range ({validation_summary(exc)}); lower its tolerance's spread"
                ) from None
    return unit
