"""The sweep file: which sensor parameters to vary, how, and what to ask of the results.

A sweep is a TOML file (or the same dict in Python) with one ``[sweep]`` table
and an optional ``[benchmark]`` table holding the protocol, exactly as
``sdt benchmark`` reads it::

    [sweep]
    base = "adxl345"                 # any sensor name, catalogue part with mode, or TOML file
    design = "grid"                  # grid | lhs | sobol | morris
    [sweep.axes]
    sampling_rate_hz = { levels = [800, 1600, 3200, 6400] }
    noise_density_ug_rthz = { range = [25, 1000], scale = "log", steps = 4 }
    [sweep.ties]
    digital_cutoff_hz = "0.4999 * rate"

An axis may also be a chain-stage parameter, ``"nonlinearity.second_pct_fs"``:
its spelling (:func:`is_stage_key`, and TOML's unquoted dotted keys read as
one by :func:`flatten_stage_keys`) is part of this model; it is checked
against the registry's stages where the base sensor is resolved
(:mod:`~sdt_framework.explore.stage_axes`). The designs are the entries of
:data:`~sdt_framework.explore.designs.DESIGNS`. Reading the file is
:mod:`~sdt_framework.explore.sweep_file`.
"""

from __future__ import annotations

import re
from typing import Any, Literal

import numpy as np
from pydantic import Field, field_validator, model_validator

from .designs import DESIGNS
from .target import SweepModel as _Model
from .target import Target
from .ties import check_tie

__all__ = [
    "DEMAND",
    "SHORT_NAMES",
    "SWEEPABLE",
    "Axis",
    "CostTerm",
    "Sweep",
    "Target",
    "axis_levels",
    "flatten_stage_keys",
    "is_stage_key",
]

#: SensorSpec field -> short name used in point names, ties and plots
SHORT_NAMES: dict[str, str] = {
    "sampling_rate_hz": "rate",
    "full_scale_g": "range",
    "adc_bits": "bits",
    "noise_density_ug_rthz": "nsd",
    "mech_cutoff_hz": "fmech",
    "analog_cutoff_hz": "fana",
    "digital_cutoff_hz": "fdig",
    "digital_order": "dorder",
}
SWEEPABLE = tuple(SHORT_NAMES)
INTEGER_FIELDS = frozenset({"adc_bits", "digital_order"})

#: Which way a parameter is more demanding of the part (and so costs more):
#: "higher" means a larger value is the harder specification to meet.
DEMAND: dict[str, Literal["higher", "lower"]] = {
    "sampling_rate_hz": "higher",
    "full_scale_g": "higher",
    "adc_bits": "higher",
    "noise_density_ug_rthz": "lower",
    "mech_cutoff_hz": "higher",
    "analog_cutoff_hz": "higher",
    "digital_cutoff_hz": "higher",
    "digital_order": "higher",
}


#: ``<stage>.<param>``: a registered stage's name (as sensor names are spelt) and a parameter
STAGE_KEY = re.compile(r"^[a-z0-9][a-z0-9._-]*\.[A-Za-z_][A-Za-z0-9_]*$")
#: the design names, in the order of the table of designs
DesignName = Literal[tuple(DESIGNS)]  # type: ignore[valid-type]


def is_stage_key(key: str) -> bool:
    """Whether ``key`` is spelt as a stage parameter, ``"<stage>.<param>"``."""
    return bool(STAGE_KEY.match(key))


def flatten_stage_keys(table: Any, fields: tuple[str, ...], leaf: type) -> Any:
    """``{stage: {param: x}}`` -> ``{"stage.param": x}``, for TOML's unquoted dotted keys.

    ``nonlinearity.second_pct_fs = {levels = [...]}`` in TOML is a nested
    table; a key that is not a SensorSpec field and maps to a table whose
    values are all ``leaf`` (axis or cost tables: dict; ties: str) is read as
    a stage's parameters.
    """
    if not isinstance(table, dict):
        return table
    out: dict[str, Any] = {}
    for key, value in table.items():
        if (
            key not in fields
            and isinstance(value, dict)
            and value
            and all(isinstance(v, leaf) for v in value.values())
        ):
            out.update({f"{key}.{param}": v for param, v in value.items()})
        else:
            out[key] = value
    return out


class Axis(_Model):
    """One swept parameter: explicit ``levels``, or a ``range`` sampled on a scale."""

    levels: list[float] | None = Field(default=None, description="Explicit values, in SI units.")
    range: tuple[float, float] | None = Field(default=None, description="[low, high] bounds.")
    scale: Literal["linear", "log"] = Field(default="linear", description="Spacing of a range.")
    steps: int = Field(default=4, ge=2, description="Grid levels drawn from a range.")

    @model_validator(mode="after")
    def _one_of(self) -> Axis:
        if (self.levels is None) == (self.range is None):
            raise ValueError("give either `levels = [...]` or `range = [low, high]`")
        if self.levels is not None:
            if not self.levels:
                raise ValueError("levels is empty: list at least one value")
            if len(set(self.levels)) != len(self.levels):
                raise ValueError(f"levels {self.levels} repeat a value")
        if self.range is not None:
            low, high = self.range
            if not low < high:
                raise ValueError(f"range low {low:g} must be below high {high:g}")
            if self.scale == "log" and low <= 0:
                raise ValueError(f"a log-scale range needs low > 0 (got {low:g})")
        return self


def axis_levels(axis: Axis) -> list[float]:
    """The grid levels of an axis: its explicit levels, or ``steps`` across its range."""
    if axis.levels is not None:
        return [float(v) for v in axis.levels]
    low, high = axis.range  # type: ignore[misc]
    if axis.scale == "log":
        return list(np.geomspace(low, high, axis.steps))
    return list(np.linspace(low, high, axis.steps))


class CostTerm(_Model):
    """Cost of moving a parameter away from the base, per step on its scale.

    A step is a doubling (``scale = "log"``) or one unit (``"linear"``) in the
    parameter's demanding direction; moving the other way earns the cost back.
    """

    weight: float = Field(default=1.0, description="Cost units per step.")
    scale: Literal["linear", "log"] = Field(default="log", description="What one step is.")
    demand: Literal["higher", "lower", "neither"] | None = Field(
        default=None,
        description="Override which direction is more demanding ('neither': not a "
        "specification, no minimum level and no cost).",
    )


class Sweep(_Model):
    """A validated sweep: base sensor, axes, design, ties, cost model and target."""

    base: str = Field(description="Sensor the points start from (name, part[mode] or TOML).")
    design: DesignName = Field(default="grid")
    samples: int = Field(
        default=16, ge=1, description="lhs: points; sobol: base N (power of 2); morris: paths."
    )
    levels: int = Field(default=4, ge=2, description="morris: grid levels per parameter.")
    seed: int = Field(default=0, ge=0, description="Seed of the lhs/sobol/morris design.")
    axes: dict[str, Axis] = Field(
        min_length=1, description="SensorSpec field or 'stage.parameter' -> Axis."
    )
    ties: dict[str, str] = Field(default_factory=dict, description="key -> expression.")
    cost: dict[str, CostTerm] = Field(default_factory=dict, description="field -> cost term.")
    base_cost: float | None = Field(
        default=None, description="Cost of the base point (default: its price, else 0)."
    )
    target: Target = Field(default_factory=lambda: Target(max_loss=0.05))

    @model_validator(mode="before")
    @classmethod
    def _flatten(cls, data: Any) -> Any:
        """TOML's unquoted ``stage.param = ...`` keys arrive as nested tables: flatten them."""
        if not isinstance(data, dict):
            return data
        leaves = {"axes": dict, "cost": dict, "ties": str}
        return {
            k: flatten_stage_keys(v, SWEEPABLE, leaves[k]) if k in leaves else v
            for k, v in data.items()
        }

    @field_validator("axes", "cost")
    @classmethod
    def _sweepable(cls, value: dict[str, Any]) -> dict[str, Any]:
        for key in value:
            if key not in SWEEPABLE and not is_stage_key(key):
                raise ValueError(
                    f"{key!r} is not a sweepable field; choose from {', '.join(SWEEPABLE)}, "
                    f"or a stage parameter 'stage.param' (e.g. 'nonlinearity.second_pct_fs')"
                )
        return value

    @model_validator(mode="after")
    def _check_names(self) -> Sweep:
        for key, expression in self.ties.items():
            if key not in SWEEPABLE and not is_stage_key(key):
                raise ValueError(f"tie {key!r} is not a sweepable field or stage parameter")
            if key in self.axes:
                raise ValueError(f"{key!r} is both swept and tied; keep one")
            check_tie(key, expression, SHORT_NAMES)
        design = DESIGNS[self.design]
        explicit = [k for k, a in self.axes.items() if a.range is None]
        if design.needs_ranges and explicit:
            raise ValueError(
                f"design {self.design!r} needs ranges, but {explicit} give levels; "
                f"use design = 'grid' or give `range = [low, high]`"
            )
        if design.power_of_two and self.samples & (self.samples - 1):
            raise ValueError(f"{self.design} needs samples as a power of two (got {self.samples})")
        if self.samples < design.min_samples:
            raise ValueError(
                f"{self.design} needs samples >= {design.min_samples} (got {self.samples}): "
                f"{design.min_samples_why}"
            )
        if len(self.axes) < design.min_axes:
            raise ValueError(
                f"{self.design} needs at least {design.min_axes} axes (got {len(self.axes)}): "
                f"{design.min_axes_why}"
            )
        return self
