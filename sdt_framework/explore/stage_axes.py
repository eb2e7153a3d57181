"""Stage-parameter axes: sweeping a stage plugin's parameter (``"nonlinearity.second_pct_fs"``).

A sweep key ``"<stage>.<param>"`` (spelt as :func:`~sdt_framework.explore.sweep.is_stage_key`
says) names a numeric (float or int) parameter of
a registered stage's parameter model. A point sets it on the base profile's
first listed stage of that name, or adds the stage (its other parameters at
their defaults) when the base does not list it. The key itself is the
parameter's short name in point names, tables and plots
(``adxl345~rate=1600,nonlinearity.second_pct_fs=0.5``).

Which way is more demanding: an error term's magnitude is harder to make the
lower it is, so stage parameters default to ``"lower"``, ranked by their
magnitude ``|value|`` (a -2 % and a +2 % scale error are the same
specification). Parameters that are not error magnitudes (a correlation time,
a reference full scale) are ``"neither"``: the minimum specification refuses
them with a note and they cost nothing, unless the sweep's ``[sweep.cost]``
gives their ``demand``. A plugin marks such a parameter with
``Field(json_schema_extra={"demand": "neither"})``.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from pydantic import BaseModel

from ..errors import SDTError, SpecFileError
from .sweep import Sweep, axis_levels, is_stage_key

if TYPE_CHECKING:
    from ..registry import Registry
    from ..specs import SensorSpec
    from ..stages import StageSpec

__all__ = [
    "NOT_MAGNITUDES",
    "StageAxis",
    "base_value",
    "check_stage_axes",
    "stage_demand",
]

#: built-in stage parameters that are not error magnitudes: no direction is more demanding
NOT_MAGNITUDES: dict[str, str] = {
    "gauss-markov.tau_s": "a correlation time, not an error magnitude",
    "nonlinearity.full_scale_g": "the full scale the % figures refer to, not an error magnitude",
}
_NUMERIC = (float, int, float | None, int | None)


def stage_demand(key: str, spec: StageSpec | None = None) -> str:
    """Default demanding direction of a stage parameter: "lower", or "neither"."""
    if spec is not None:
        info = spec.params.model_fields.get(key.partition(".")[2])
        extra = info.json_schema_extra if info is not None else None
        if isinstance(extra, dict) and extra.get("demand") in ("higher", "lower", "neither"):
            return str(extra["demand"])
    return "neither" if key in NOT_MAGNITUDES else "lower"


@dataclass(frozen=True)
class StageAxis:
    """A checked stage-parameter key: its stage spec, type, default and direction."""

    key: str
    stage: str
    param: str
    spec: Any = field(repr=False)  # the StageSpec
    integer: bool
    demand: str
    why: str = ""


def _numeric(model: type[BaseModel]) -> list[str]:
    return sorted(k for k, f in model.model_fields.items() if f.annotation in _NUMERIC)


def _closest(word: str, options: list[str]) -> str:
    close = difflib.get_close_matches(word, options, n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _axis(key: str, table: Mapping[str, StageSpec]) -> StageAxis:
    """The stage axis of ``key``, or ValueError naming the stage's numeric parameters."""
    stage, _, param = key.partition(".")
    spec = table.get(stage)
    if spec is None:
        raise ValueError(
            f"{key!r}: no stage {stage!r} is registered{_closest(stage, sorted(table))}; "
            f"registered stages: {', '.join(sorted(table)) or '(none)'}"
        )
    numeric = _numeric(spec.params)
    if param not in numeric:
        raise ValueError(
            f"{key!r} is not a numeric parameter of stage {stage!r}{_closest(param, numeric)}; "
            f"its numeric parameters: {', '.join(numeric) or '(none)'}"
        )
    integer = spec.params.model_fields[param].annotation in (int, int | None)
    demand = stage_demand(key, spec)
    why = NOT_MAGNITUDES.get(key, "declared by the stage") if demand == "neither" else ""
    return StageAxis(key, stage, param, spec, integer, demand, why)


def _listed(base: SensorSpec, stage: str) -> Any:
    return next((use for use in base.stages if use.name == stage), None)


def base_value(base: SensorSpec, key: str, axes: Mapping[str, StageAxis] | None = None) -> float:
    """The base's value of a field or stage parameter.

    For a stage the base does not list: the parameter's default; 0 for an
    error magnitude without one (the error is absent); else NaN.
    """
    if not is_stage_key(key):
        value = getattr(base, key)
        return float("nan") if value is None else float(value)
    stage, _, param = key.partition(".")
    use = _listed(base, stage)
    if use is not None and use.params.get(param) is not None:
        return float(use.params[param])
    axis = (axes or {}).get(key)
    info = axis.spec.params.model_fields.get(param) if axis is not None else None
    if info is not None and info.is_required() and axis.demand == "lower":
        return 0.0  # an error magnitude of a stage the base lacks: the error is absent
    if info is None or info.is_required():
        return float("nan")
    default = info.get_default(call_default_factory=True)
    return float("nan") if default is None else float(default)


def check_stage_axes(
    sweep: Sweep, base: SensorSpec, registry: Registry, where: object = "sweep"
) -> dict[str, StageAxis]:
    """Check every stage key of the sweep against the registry and the base; before any work.

    Raises
    ------
    SpecFileError
        An unknown stage or non-numeric parameter; a stage the base does not
        list whose required parameters neither an axis nor a tie sets; a log
        cost over a zero level; a cost term with no demanding direction.
    """
    table = {spec.name: spec for spec in registry.stages()}
    axes: dict[str, StageAxis] = {}
    for section, keys in (("axes", sweep.axes), ("ties", sweep.ties), ("cost", sweep.cost)):
        for key in (k for k in keys if is_stage_key(k)):
            try:
                axes[key] = _axis(key, table)
            except ValueError as exc:
                raise SpecFileError(where, f"sweep.{section}", str(exc)) from None
    set_here = set(sweep.axes) | set(sweep.ties)
    for axis in axes.values():
        if axis.key not in set_here or _listed(base, axis.stage) is not None:
            continue
        missing = [
            name
            for name, info in axis.spec.params.model_fields.items()
            if info.is_required() and f"{axis.stage}.{name}" not in set_here
        ]
        if missing:
            raise SpecFileError(
                where,
                "sweep.axes" if axis.key in sweep.axes else "sweep.ties",
                f"{axis.key!r}: the base {base.name!r} does not list stage {axis.stage!r}, "
                f"whose {', '.join(missing)} {'has' if len(missing) == 1 else 'have'} no "
                f"default; list the stage in the base profile "
                f"with those params, or set them with a tie (e.g. "
                f'"{axis.stage}.{missing[0]}" = "1")',
            )
    _check_costs(sweep, base, axes, where)
    return {k: v for k, v in axes.items() if k in set_here}


def _check_costs(
    sweep: Sweep, base: SensorSpec, axes: Mapping[str, StageAxis], where: object
) -> None:
    for key, term in sweep.cost.items():
        if key not in axes:
            continue
        if key not in sweep.axes:
            raise SpecFileError(where, "sweep.cost", f"{key!r} is not a swept axis")
        if (term.demand or axes[key].demand) == "neither" and term.weight != 0:
            raise SpecFileError(
                where,
                "sweep.cost",
                f"{key!r} is {axes[key].why}: no direction is more demanding; give "
                f"demand = 'higher' or 'lower' to cost it",
            )
        low = min(abs(v) for v in axis_levels(sweep.axes[key]))
        if term.scale == "log" and not (low > 0 and abs(base_value(base, key, axes)) > 0):
            raise SpecFileError(
                where,
                "sweep.cost",
                f"{key!r}: a log cost needs non-zero levels and base value (one step = a "
                f"halving); use scale = 'linear'",
            )


def magnitude(values: np.ndarray, demand: str) -> np.ndarray:
    """Values ranked for the demanding direction: ``|value|`` where lower is harder."""
    return np.abs(values) if demand == "lower" else values


def finite_or_zero(value: float) -> float:
    """A base value for the cost model: an absent parameter counts from 0."""
    return 0.0 if math.isnan(value) else value


def require(sweep: Sweep, axes: Mapping[str, StageAxis] | None) -> Mapping[str, StageAxis]:
    """``axes``, or the one-line error a stage sweep gets without them."""
    keys = [k for k in (*sweep.axes, *sweep.ties) if k not in (axes or {}) and is_stage_key(k)]
    if keys:
        raise SDTError(
            f"stage parameter {keys[0]!r} needs the registry's stages: pass "
            f"check_stage_axes(sweep, base, registry) as stage_axes"
        )
    return axes or {}
