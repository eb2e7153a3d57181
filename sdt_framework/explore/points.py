"""Design points as sensor profiles: the base sensor with the point's values and ties.

Each point goes through :class:`~sdt_framework.specs.SensorSpec` validation, so
a combination the chain cannot run (a digital cutoff at or above the new
Nyquist, say, or a value that is not a finite number, such as a level of
``inf``) is not evaluated: it is returned with the reason, to be written to
``skipped_points.csv``, and the sweep goes on. A valid point the data cannot
feed (a rate above the recordings') is moved there too once the benchmark is
planned (:func:`left_out`), so every design point is in ``points.csv`` or in
``skipped_points.csv``. Stage-parameter values
(``"nonlinearity.second_pct_fs"``) go into the profile's stage list and are
checked by the stage's own parameter model the same way.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import pandas as pd
from pydantic import ValidationError

from ..errors import field_errors
from ..signals.sizes import building
from ..specs import SensorSpec
from .stage_axes import StageAxis, require
from .stage_values import with_stage_values
from .sweep import INTEGER_FIELDS, SHORT_NAMES, Sweep
from .ties import evaluate_tie

__all__ = ["Point", "build_points", "left_out", "point_name"]


@dataclass(frozen=True)
class Point:
    """One evaluated design point: its index, values and sensor profile."""

    index: int
    values: dict[str, float]
    spec: SensorSpec


def _fmt(value: float, digits: int) -> str:
    return f"{value:.{digits}g}"


def short_name(key: str) -> str:
    """A swept key's name in point names: the field's short name, or the stage key itself.

    Sensor names are lower case, so a stage parameter spelt with capitals is
    lower-cased here (only in the name).
    """
    return SHORT_NAMES.get(key, key.lower())


def point_name(base: str, values: dict[str, float], digits: int = 4) -> str:
    """Readable name of a point, e.g. ``adxl345~rate=1600,nsd=90``.

    A stage parameter appears under its key: ``adxl345~nonlinearity.second_pct_fs=0.5``.
    """
    settings = ",".join(f"{short_name(k)}={_fmt(v, digits)}" for k, v in values.items())
    return f"{base.split('~')[0]}~{settings}"


def _reason(exc: ValidationError) -> str:
    field, message = field_errors(exc)[0]
    return f"{field}: {message}" if field else message


def _resolved(sweep: Sweep, base: SensorSpec, row: dict[str, float]) -> dict[str, float]:
    """The point's swept values plus every tie evaluated on them."""
    values = {k: (int(v) if k in INTEGER_FIELDS else float(v)) for k, v in row.items()}
    scope = {**base.model_dump(include=set(SHORT_NAMES)), **values}
    scope = {k: v for k, v in scope.items() if v is not None}
    scope = {k: v for k, v in scope.items() if k in SHORT_NAMES}  # ties read fields only
    named = {**scope, **{SHORT_NAMES[k]: v for k, v in scope.items()}}
    for field, expression in sweep.ties.items():
        tied = evaluate_tie(expression, named)
        values[field] = round(tied) if field in INTEGER_FIELDS else tied
        if field in SHORT_NAMES:  # a tied stage parameter is set, never read by another tie
            named[field] = named[SHORT_NAMES[field]] = values[field]
    return values


def _finite(values: Mapping[str, float]) -> None:
    """A value of ``inf`` or NaN (a level, or a tie's result) is no specification."""
    for key, value in values.items():
        if not math.isfinite(value):
            raise ValueError(f"{key}: {value:g} is not a finite number")


def build_points(
    sweep: Sweep,
    base: SensorSpec,
    design: pd.DataFrame,
    stage_axes: Mapping[str, StageAxis] | None = None,
) -> tuple[list[Point], pd.DataFrame]:
    """Validated points, and a table of the skipped ones with their reasons.

    Names carry the swept values with 4 significant digits, more where two
    points would otherwise share a name. A sweep over stage parameters needs
    ``stage_axes``, from :func:`~sdt_framework.explore.stage_axes.check_stage_axes`.
    """
    stage_axes = require(sweep, stage_axes)
    with building(f"building the {len(design):,} sweep points", "use fewer levels or samples"):
        return _build(sweep, base, design, stage_axes)


def _build(
    sweep: Sweep, base: SensorSpec, design: pd.DataFrame, stage_axes: Mapping[str, StageAxis]
) -> tuple[list[Point], pd.DataFrame]:
    fields = list(sweep.axes)
    rows = design[fields].to_dict("records")
    digits = 4
    while len({point_name(base.name, r, digits) for r in rows}) < len(rows) and digits < 17:
        digits += 1
    points: list[Point] = []
    skipped: list[dict[str, object]] = []
    content = base.model_dump(exclude={"plugin", "distribution"})
    for index, row in zip(design["design_index"], rows, strict=True):
        name = point_name(base.name, row, digits)
        try:
            _finite(row)
            values = _resolved(sweep, base, row)
            _finite(values)
            stages = with_stage_values(content["stages"], values, stage_axes)
            spec = SensorSpec.model_validate(
                {
                    **content,
                    **{k: v for k, v in values.items() if k not in stage_axes},
                    "stages": stages,
                    "name": name,
                    "description": f"{base.name} with {', '.join(name.split('~')[1:])}",
                    "source": f"design point {int(index)} of a sweep on {base.name}",
                }
            )
        except (ValidationError, ValueError) as exc:
            reason = _reason(exc) if isinstance(exc, ValidationError) else str(exc)
            skipped.append({"design_index": int(index), "point": name, **row, "reason": reason})
            continue
        points.append(Point(int(index), values, spec))
    columns = ["design_index", "point", *fields, "reason"]
    return points, pd.DataFrame(skipped, columns=columns)


def left_out(
    points: list[Point], skipped: pd.DataFrame, reasons: Mapping[str, str], fields: list[str]
) -> tuple[list[Point], pd.DataFrame]:
    """Move the points the benchmark leaves out (name -> reason) to the skipped table."""
    kept = [p for p in points if p.spec.name not in reasons]
    moved = [
        {
            "design_index": p.index,
            "point": p.spec.name,
            **{f: p.values[f] for f in fields},
            "reason": reasons[p.spec.name],
        }
        for p in points
        if p.spec.name in reasons
    ]
    if not moved:
        return points, skipped
    table = pd.concat([skipped, pd.DataFrame(moved, columns=skipped.columns)], ignore_index=True)
    return kept, table.sort_values("design_index", kind="stable", ignore_index=True)
