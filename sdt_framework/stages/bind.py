"""Binding a profile's listed stages to the registered stage specs, and placing them.

:func:`bind_stages` is called by the registry when a profile is looked up: an
unknown stage name or parameters its model rejects become one-line
:class:`~sdt_framework.errors.SDTError` messages naming the sensor and the
stage. :func:`place` merges the bound stages with the chain's own stages in
the order :data:`~sdt_framework.stages.spec.ANCHORS` fixes.

A profile built in Python (``SensorSpec.model_validate({...})``) lists stages
no registry bound yet; the chain, below the registry, never binds them itself
(:func:`require_bound` refuses them, naming how to bind): the caller that
holds a registry binds (``Registry.bind``; ``sdt_framework.degrade`` binds in
the default registry). No registry installs a binder here: sdt's own commands
bind every stage where the sensor or its drawn unit is made (a worker process
imports only what it unpickles; :func:`~sdt_framework.stages.draw_unit` takes
the stage table).
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from typing import Any

from pydantic import ValidationError

from ..errors import SDTError, UnknownNameError, validation_summary
from ..specs import SensorSpec
from ..specs.stage_use import StageUse
from .spec import ANCHORS, StageContext, StageSpec

__all__ = [
    "bind_stages",
    "build_extra",
    "is_random",
    "place",
    "require_bound",
    "uses_node",
]


def _check(sensor: str, use: StageUse, spec: StageSpec) -> dict[str, Any]:
    where = f"sensor {sensor!r}, stage {use.name!r}"
    try:
        params = spec.params.model_validate(use.params).model_dump()
        for axis, values in (use.per_axis or {}).items():
            spec.params.model_validate({**use.params, **values})
            if set(values) - set(params):
                raise SDTError(f"{where}: per_axis.{axis} names unknown parameters {values}")
    except ValidationError as exc:
        raise SDTError(f"{where}: {validation_summary(exc)}") from None
    for key in use.tolerances:
        if not isinstance(params.get(key), int | float) or isinstance(params.get(key), bool):
            numeric = sorted(k for k, v in params.items() if isinstance(v, int | float))
            raise SDTError(
                f"{where}: tolerance on {key!r}, which is not a numeric parameter; "
                f"numeric parameters: {', '.join(numeric) or '(none)'}"
            )
    return params


def _check_stage_tolerances(sensor: SensorSpec, table: Mapping[str, StageSpec]) -> None:
    """A profile tolerance ``"stage.parameter"`` on a registered stage must name a number of it.

    A stage no selected plugin registers is not an error here: the nominal
    chain does not use it, and drawing units (``--units``) names it in one line.
    """
    for key in sorted(k for k in sensor.tolerances if "." in k):
        name, _, param = key.partition(".")
        spec = table.get(name)
        if spec is None:
            continue
        fields = spec.params.model_fields
        numeric = sorted(k for k, f in fields.items() if f.annotation in (float, int))
        if param not in numeric:
            raise SDTError(
                f"sensor {sensor.name!r}: tolerance {key!r} names no numeric parameter of "
                f"stage {name!r}; its numeric parameters: {', '.join(numeric) or '(none)'}"
            )


def bind_stages(sensor: SensorSpec, table: Mapping[str, StageSpec]) -> SensorSpec:
    """``sensor`` with each listed stage bound to its spec and its parameters validated.

    Raises
    ------
    UnknownNameError
        A listed stage no plugin registered (lists the registered ones).
    SDTError
        Parameters, per-axis values or tolerances the stage's model rejects.
    """
    _check_stage_tolerances(sensor, table)
    if not sensor.stages:
        return sensor
    bound = []
    for use in sensor.stages:
        if use.spec is not None:  # bound already (by the registry the profile came from)
            bound.append(use)
            continue
        spec = table.get(use.name)
        if spec is None:
            raise UnknownNameError("stage", use.name, table, note=f"(listed by {sensor.name!r})")
        params = _check(sensor.name, use, spec)
        bound.append(use.model_copy(update={"params": params, "spec": spec}))
    samplers = [use.name for use in bound if use.spec.domain == "sampler"]
    if len(samplers) > 1:
        raise SDTError(f"sensor {sensor.name!r}: at most one sampler stage, got {samplers}")
    return sensor.model_copy(update={"stages": tuple(bound)})


def require_bound(sensor: SensorSpec) -> SensorSpec:
    """``sensor`` if every stage it lists is bound to its spec; else refused, naming them.

    Raises
    ------
    SDTError
        Unbound stages (a profile built in Python, not looked up in a registry):
        bind it first with ``Registry.bind(sensor)``, or call
        ``sdt_framework.degrade``, which binds in the default registry.
    """
    unbound = [use.name for use in sensor.stages if use.spec is None]
    if unbound:
        raise SDTError(
            f"sensor {sensor.name!r} lists stages {unbound} no registry bound in this process "
            f"(pid {os.getpid()}); bind it first with Registry.bind(sensor), or call "
            f"sdt_framework.degrade, which binds it in the default registry"
        )
    return sensor


def is_random(sensor: SensorSpec) -> bool:
    """Whether ``sensor``'s chain draws random numbers (white noise or a random stage)."""
    if sensor.inject_noise and sensor.noise_density_ug_rthz > 0:
        return True
    return any(use.spec is None or use.spec.random for use in sensor.stages)


def uses_node(sensor: SensorSpec) -> bool:
    """Whether ``sensor``'s bound chain has a node stage (one that reads the other axes)."""
    return any(use.spec is not None and use.spec.node for use in sensor.stages)


def build_extra(sensor: SensorSpec, fs: float) -> list[tuple[StageSpec, Any]]:
    """(spec, stage object) of every bound extra stage of ``sensor`` at recording rate ``fs``."""
    target = float(sensor.sampling_rate_hz)
    built = []
    for i, use in enumerate(sensor.stages):
        spec: StageSpec = use.spec
        context = StageContext(
            fs=target if spec.domain == "digital" else float(fs),
            recording_hz=float(fs),
            target_hz=target,
            full_scale_g=sensor.full_scale_g,
            label=f"{use.name}.{i}",
            sensor=sensor.name,
        )
        built.append((spec, spec.factory(spec.params.model_validate(use.params), context)))
    return built


def place(own: Mapping[str, Any], extra: Sequence[tuple[StageSpec, Any]]) -> list[Any]:
    """The chain's own stages (by anchor name, absent ones left out) with the extras placed.

    Extras placed at the same spot keep the order the profile lists them in;
    ``own["decimation"]`` (a decimating part's low-pass) runs right before the
    sampler, after the extras placed before it; a
    sampler stage replaces ``own["sample"]`` (and runs even where the rates
    are equal and the chain has no sampler of its own).
    """
    groups: dict[tuple[str, str], list[Any]] = {}
    sampler = None
    for spec, stage in extra:
        if spec.domain == "sampler":
            sampler = stage
            continue
        groups.setdefault((spec.where, spec.anchor), []).append(stage)
    out: list[Any] = []
    for anchor in ANCHORS:
        out += groups.get(("before", anchor), [])
        if anchor == "sample" and own.get("decimation") is not None:
            out.append(own["decimation"])  # a sigma-delta part's filter, just before its sampler
        stage = sampler if anchor == "sample" and sampler is not None else own.get(anchor)
        if stage is not None:
            out.append(stage)
        out += groups.get(("after", anchor), [])
    return out
