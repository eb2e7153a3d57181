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
require_bound(sensor)
    ``sensor`` if its stages are bound (the chain's check; a registry binds).
draw_unit(sensor, seed, k)
    Unit k of a sensor, drawn from its tolerances.
row_normals(ctx, label, rows, n), TemperatureProfile
    Helpers for stage authors: per-acquisition draws, a temperature profile.
"""

from __future__ import annotations

from ..specs.stage_use import StageUse, Tolerance
from .bind import bind_stages, build_extra, is_random, place, require_bound, uses_node
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
    "bind_stages",
    "build_extra",
    "draw_unit",
    "has_tolerances",
    "is_random",
    "place",
    "require_bound",
    "row_normals",
    "uses_node",
]
