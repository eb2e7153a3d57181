"""Physical units of a sensor drawn from its profile's tolerances (a per-unit Monte Carlo).

Unit ``k`` of a sensor draws each toleranced parameter from
``rng(seed, "unit", base_name, k, parameter)``: the same unit in every run
with the same base seed, whatever the other sensors, repetitions or
recordings, and whichever mode of a part is selected (``base_name`` drops the
mode and design-point suffixes). Each parameter has its own stream, so adding
a tolerance to one parameter leaves the others' draws as they were.
"""

from __future__ import annotations

from typing import Any

from pydantic import ValidationError

from ..errors import SDTError, validation_summary
from ..seeding import rng
from ..specs import MODE_SUFFIX, POINT_SUFFIX, SensorSpec
from ..stage_use import StageUse, Tolerance

__all__ = ["base_name", "draw", "draw_unit", "has_tolerances"]

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


def draw_unit(sensor: SensorSpec, seed: int, k: int) -> SensorSpec:
    """Unit ``k`` of ``sensor``: every toleranced value drawn, tolerances dropped.

    A tolerance ``"stage.parameter"`` applies to the listed stage of that
    name, or adds the stage (nominal value 0) to the unit when the profile
    does not list it: a profile's nominal chain stays as it is.

    A sensor without tolerances is returned as it is (every unit is nominal).
    A drawn value the model refuses (a negative noise density) is a one-line
    :class:`~sdt_framework.errors.SDTError` asking for a smaller spread.
    """
    if not has_tolerances(sensor):
        return sensor
    base = base_name(sensor.name)
    update: dict[str, Any] = {"tolerances": {}}
    added: dict[str, dict[str, float]] = {}
    for key in sorted(sensor.tolerances):
        stage, _, param = key.partition(".")
        if param:  # a stage's parameter: on the listed stage, or on one added to the unit
            listed = [use for use in sensor.stages if use.name == stage]
            nominal = float(listed[0].params.get(param, 0.0)) if listed else 0.0
            value = draw(sensor.tolerances[key], nominal, seed, "unit", base, k, key)
            added.setdefault(stage, {})[param] = value
            continue
        nominal = float(getattr(sensor, key))
        update[key] = draw(sensor.tolerances[key], nominal, seed, "unit", base, k, key)
    stages = []
    for i, use in enumerate(sensor.stages):
        params = dict(use.params)
        for key in sorted(use.tolerances):
            where = f"{use.name}.{i}.{key}"
            params[key] = draw(
                use.tolerances[key], float(params[key]), seed, "unit", base, k, where
            )
        params.update(added.pop(use.name, {}))
        stages.append(use.model_copy(update={"params": params, "tolerances": {}}))
    stages += [StageUse(name=name, params=params) for name, params in sorted(added.items())]
    update["stages"] = tuple(stages)
    data = {**sensor.model_dump(), **update}
    try:
        unit = SensorSpec.model_validate({**data, "stages": ()})
    except ValidationError as exc:
        raise SDTError(
            f"sensor {sensor.name!r}, unit {k}: a drawn value is out of range "
            f"({validation_summary(exc)}); lower its tolerance's spread"
        ) from None
    unit = unit.model_copy(update={"stages": tuple(stages)})
    if any(use.spec is None for use in unit.stages):
        return unit  # bound (and checked) when its chain is compiled
    for use in unit.stages:
        if use.spec is not None:
            try:
                use.spec.params.model_validate(use.params)
            except ValidationError as exc:
                raise SDTError(
                    f"sensor {sensor.name!r}, unit {k}, stage {use.name!r}: a drawn value is "
                    f"out of range ({validation_summary(exc)}); lower its tolerance's spread"
                ) from None
    return unit
