"""A profile's extra chain stages and per-unit tolerances, as data.

They are part of the sensor profile's data model, so they live with the
specs and a :class:`~sdt_framework.specs.SensorSpec` lists them; the stage
specs they name live in :mod:`sdt_framework.stages`, one layer up, which
binds them (``StageUse.spec``).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

__all__ = ["StageUse", "Tolerance"]


class Tolerance(BaseModel):
    """Unit-to-unit spread of one parameter: what a batch of real parts scatters by.

    A unit's value is the nominal value plus ``spread`` times a draw from the
    distribution: standard normal (truncated at +-3) or uniform on [-1, 1].
    ``spread`` is in the parameter's unit; ``spread_pct`` is in percent of the
    nominal value instead. ``per_axis`` gives the spread on the Y or Z axis of
    a stage parameter (``spread`` is then the X axis): each axis listed there
    is drawn on its own, as the separate sensing element it is; an axis not
    listed shares the X axis's value.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    distribution: Literal["normal", "uniform"] = Field(
        default="normal", description="normal: spread is the SD; uniform: the half-width."
    )
    spread: float | None = Field(default=None, ge=0, description="In the parameter's unit.")
    spread_pct: float | None = Field(default=None, ge=0, description="In % of the nominal value.")
    per_axis: dict[Literal["y", "z"], Annotated[float, Field(ge=0)]] | None = Field(
        default=None, description="Spread on the Y or Z axis (a stage parameter), its unit."
    )

    @model_validator(mode="after")
    def _one_spread(self) -> Tolerance:
        if (self.spread is None) == (self.spread_pct is None):
            raise ValueError("give exactly one of spread or spread_pct")
        return self

    def on_axis(self, axis: str) -> Tolerance:
        """This tolerance as it applies on ``axis`` (its own spread there, if any)."""
        spread = (self.per_axis or {}).get(axis)  # type: ignore[call-overload]
        if spread is None:
            return self
        return Tolerance(distribution=self.distribution, spread=spread)

    def half_width(self, nominal: float) -> float:
        """The spread in the parameter's unit, for a nominal value."""
        if self.spread is not None:
            return self.spread
        return abs(nominal) * float(self.spread_pct or 0.0) / 100.0


class StageUse(BaseModel):
    """One extra stage a sensor profile lists: its name, parameters and tolerances.

    ``per_axis`` overrides parameters on the Y or Z axis (the parameters are
    the X axis), like :attr:`SensorSpec.per_axis`. ``spec`` is bound by the
    registry when the profile is looked up, never written by hand.
    """

    model_config = ConfigDict(frozen=True, extra="forbid", arbitrary_types_allowed=True)

    name: str = Field(description="Name of a registered stage, e.g. 'offset'.")
    params: dict[str, Any] = Field(default_factory=dict, description="The stage's parameters.")
    per_axis: dict[Literal["x", "y", "z"], dict[str, Any]] | None = Field(
        default=None, description="Parameter values on another axis."
    )
    tolerances: dict[str, Tolerance] = Field(
        default_factory=dict, description="Unit-to-unit spread of numeric parameters."
    )
    spec: Any = Field(default=None, exclude=True, description="The bound StageSpec.")

    def for_axis(self, axis: str) -> StageUse:
        """This use on ``axis``: that axis's parameter values, if any."""
        values = (self.per_axis or {}).get(axis)  # type: ignore[call-overload]
        if not values:
            return self
        return self.model_copy(update={"params": {**self.params, **values}})
