"""A design point's stage list: the swept stage parameters set, and checked by each stage.

A value goes to the base profile's first listed stage of that name, on every
axis (a ``per_axis`` override of the parameter is dropped), or to the stage
appended to the list when the base does not list it. The stage's own
parameter model checks the result; a rejected value skips the point, with
one exception: 0 for an error magnitude that the model requires to be
positive (gauss-markov ``sigma_ug``, flicker, random-walk, vrw, white-noise)
means the error is absent, which is the stage left out: the limit of the
process as its magnitude goes to 0, and the base's own chain when the base
does not list the stage.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pydantic import ValidationError

from ..errors import validation_summary
from .stage_axes import StageAxis

__all__ = ["with_stage_values"]


def _absent(exc: ValidationError, stage: str, params: dict, axes: Mapping[str, StageAxis]) -> bool:
    """Whether every error is a swept error magnitude at 0 (the stage is then left out)."""
    for error in exc.errors():
        param = str(error["loc"][0]) if error["loc"] else ""
        axis = axes.get(f"{stage}.{param}")
        if axis is None or axis.demand != "lower" or params.get(param) != 0:
            return False
    return True


def with_stage_values(
    stages: list[dict[str, Any]], values: Mapping[str, float], axes: Mapping[str, StageAxis]
) -> list[dict[str, Any]]:
    """A profile's stage list (as dicts) with the point's stage values set, each stage checked.

    Raises ValueError with the reason when a stage's model rejects its
    parameters (the point is skipped); see the module docstring for 0.
    """
    out = [
        {
            **use,
            "params": dict(use.get("params") or {}),
            "per_axis": {a: dict(v) for a, v in (use.get("per_axis") or {}).items()} or None,
        }
        for use in stages
    ]
    touched: dict[str, dict[str, Any]] = {}
    for key, value in values.items():
        axis = axes.get(key)
        if axis is None:
            continue
        use = next((u for u in out if u["name"] == axis.stage), None)
        if use is None:
            use = {"name": axis.stage, "params": {}}
            out.append(use)
        use["params"][axis.param] = round(value) if axis.integer else float(value)
        for override in (use.get("per_axis") or {}).values():
            override.pop(axis.param, None)
        touched[axis.stage] = use
    absent = []
    for name, use in touched.items():
        model = axes[next(k for k, a in axes.items() if a.stage == name)].spec.params
        try:
            model.model_validate(use["params"])
            for override in (use.get("per_axis") or {}).values():
                model.model_validate({**use["params"], **override})
        except ValidationError as exc:
            if not _absent(exc, name, use["params"], axes):
                raise ValueError(f"stage {name!r}: {validation_summary(exc)}") from None
            absent.append(use)
    return [use for use in out if not any(use is gone for gone in absent)]
