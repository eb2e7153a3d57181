"""Chain-stage plugins: specs, binding to profiles, random draws, units, temperature.

Public API
----------
StageSpec, StageContext, ANCHORS
    What a stage plugin registers through ``register_stages(register)``, what
    its factory is told, and the built-in stages it is placed against.
StageUse, Tolerance
    A profile's extra stage (name, parameters, tolerances), and a tolerance.
bind_stages(sensor, table), is_random(sensor), uses_node(sensor)
    Bind a profile's stages to the registered specs; whether its chain is
    random; whether it reads a triaxial node's other axes.
bind_listed(sensor), install_stage_binder(binder)
    Bind a profile built in Python with the binder the registry installed.
draw_unit(sensor, seed, k)
    Unit k of a sensor, drawn from its tolerances.
row_normals(ctx, label, rows, n), TemperatureProfile
    Helpers for stage authors: per-acquisition draws, a temperature profile.
"""

from __future__ import annotations

from ..specs.stage_use import StageUse, Tolerance
from .bind import (
    bind_listed,
    bind_stages,
    build_extra,
    install_stage_binder,
    is_random,
    place,
    uses_node,
)
from .draws import row_normals
from .spec import ANCHORS, StageContext, StageSpec
from .temperature import TemperatureProfile
from .units import base_name, draw_unit, has_tolerances

__all__ = [
    "ANCHORS",
    "StageContext",
    "StageSpec",
    "StageUse",
    "TemperatureProfile",
    "Tolerance",
    "base_name",
    "bind_listed",
    "bind_stages",
    "build_extra",
    "draw_unit",
    "has_tolerances",
    "install_stage_binder",
    "is_random",
    "place",
    "row_normals",
    "uses_node",
]
