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

An axis may also be a chain-stage parameter, ``"nonlinearity.second_pct_fs"``
(:mod:`~sdt_framework.explore.stage_axes`): spelt right here, checked against
the registry's stages where the base sensor is resolved. Every error names the
sweep file, the key and what to do, before any work.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Literal

from pydantic import (
    BaseModel,
    ConfigDict,
    Field,
    ValidationError,
    field_validator,
    model_validator,
)

from ..bench.config_paths import resolve_written, written_by_sdt
from ..errors import SpecFileError
from ..toml_files import read_toml
from .stage_axes import flatten_stage_keys, is_stage_key
from .ties import check_tie

__all__ = [
    "DEMAND",
    "SHORT_NAMES",
    "SWEEPABLE",
    "Axis",
    "CostTerm",
    "Sweep",
    "Target",
    "load_sweep",
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


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


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


class Target(_Model):
    """The diagnostic performance a specification must reach (give exactly one)."""

    macro_f1: float | None = Field(default=None, gt=0, le=1, description="Absolute Macro-F1.")
    fraction_of_reference: float | None = Field(
        default=None, gt=0, le=1, description="Share of the reference's Macro-F1."
    )
    max_loss: float | None = Field(
        default=None, ge=0, lt=1, description="Largest Macro-F1 loss to the reference."
    )
    max_loss_to_base: float | None = Field(
        default=None,
        ge=0,
        lt=1,
        description="Largest Macro-F1 loss to the base sensor (how much error it tolerates).",
    )

    @model_validator(mode="after")
    def _exactly_one(self) -> Target:
        given = [self.macro_f1, self.fraction_of_reference, self.max_loss, self.max_loss_to_base]
        if sum(v is not None for v in given) != 1:
            raise ValueError(
                "give exactly one of macro_f1, fraction_of_reference, max_loss, max_loss_to_base"
            )
        return self

    def describe(self) -> str:
        """The target in words, for tables and the report."""
        if self.macro_f1 is not None:
            return f"Macro-F1 >= {self.macro_f1:g}"
        if self.fraction_of_reference is not None:
            return f">= {self.fraction_of_reference:g} x reference Macro-F1"
        if self.max_loss is not None:
            return f"loss to reference <= {self.max_loss:g}"
        return f"loss to base <= {self.max_loss_to_base:g}"


class Sweep(_Model):
    """A validated sweep: base sensor, axes, design, ties, cost model and target."""

    base: str = Field(description="Sensor the points start from (name, part[mode] or TOML).")
    design: Literal["grid", "lhs", "sobol", "morris"] = Field(default="grid")
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
        if self.design != "grid" and any(a.range is None for a in self.axes.values()):
            explicit = [k for k, a in self.axes.items() if a.range is None]
            if self.design in ("sobol", "morris"):
                raise ValueError(
                    f"design {self.design!r} needs ranges, but {explicit} give levels; "
                    f"use design = 'grid' or give `range = [low, high]`"
                )
        if self.design == "sobol" and self.samples & (self.samples - 1):
            raise ValueError(f"sobol needs samples as a power of two (got {self.samples})")
        return self


def _where(exc: ValidationError) -> tuple[str, str]:
    first = exc.errors()[0]
    field = ".".join(str(p) for p in first["loc"])
    reason = first["msg"].removeprefix("Value error, ")
    if first["type"] == "extra_forbidden":
        reason = "unknown key"
    return field, reason


def load_sweep(path: str | os.PathLike[str]) -> tuple[Sweep, dict[str, Any]]:
    """Read ``path``: the validated sweep and the raw ``[benchmark]`` table (protocol)."""
    path = Path(path)
    data = read_toml(
        path, what="sweep file", missing="sweep file not found; `sdt explore --example` prints one"
    )
    unknown = sorted(set(data) - {"sweep", "benchmark"})
    if unknown:
        raise SpecFileError(path, unknown[0], "unknown table; a sweep has [sweep] and [benchmark]")
    if "sweep" not in data:
        raise SpecFileError(path, "sweep", "missing; `sdt explore --example` shows the format")
    protocol = data.get("benchmark", {})
    if not isinstance(protocol, dict):
        raise SpecFileError(
            path, "benchmark", f"must be a table of options, got {type(protocol).__name__}"
        )
    if written_by_sdt(path):  # an exploration's own sweep.toml: paths relative to its folder
        protocol = resolve_written(protocol, path.parent)
    return parse_sweep(data["sweep"], path), dict(protocol)


def parse_sweep(table: dict[str, Any], where: str | os.PathLike[str] = "sweep") -> Sweep:
    """Validate a ``[sweep]`` table; errors name ``where`` and the key."""
    try:
        return Sweep.model_validate(table)
    except ValidationError as exc:
        field, reason = _where(exc)
        raise SpecFileError(where, f"sweep.{field}" if field else "sweep", reason) from None
