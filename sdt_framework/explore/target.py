"""What a sweep asks of its points: the ``[sweep.target]`` table, validated.

One Macro-F1 rule (exactly one of ``macro_f1``, ``fraction_of_reference``,
``max_loss``, ``max_loss_to_base``), and optionally constraints beside it:

    [sweep.target]
    max_loss = 0.05
    zone_agreement = 0.95            # share of windows in the reference's ISO zone
    min_battery_life_years = 5.0     # the node's life on its battery
    battery = "2xAA"                 # the cell the life is counted on (default)
    report_interval = "10min"        # one report per interval (default)

``battery`` and ``report_interval`` also set the battery life that pareto.csv
and the front with life carry, with or without a life constraint. Pass or
fail is decided in :mod:`.objectives` only; this module says what was asked.
"""

from __future__ import annotations

import re
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from ..edge.cells import CELLS
from ..edge.interval import format_interval, parse_interval
from ..errors import SDTError

__all__ = ["SweepModel", "Target"]


class SweepModel(BaseModel):
    """The sweep file's models: unknown keys, inf/nan and true/false are refused."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)

    @model_validator(mode="before")
    @classmethod
    def _no_booleans(cls, data: Any) -> Any:
        """``true``/``false`` is not a number: pydantic would read it as 1/0, so it is refused."""
        if isinstance(data, dict):
            for key, value in data.items():
                values = value if isinstance(value, list | tuple) else [value]
                if key in cls.model_fields and any(isinstance(v, bool) for v in values):
                    raise ValueError(
                        f"{key}: true/false is not a number (it would be read as 1/0); give numbers"
                    )
        return data


class Target(SweepModel):
    """What a specification must reach: one Macro-F1 rule, and optionally ``zone_agreement``
    (:mod:`.zones`) and ``min_battery_life_years`` (:mod:`.life`) beside it."""

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

    zone_agreement: float | None = Field(
        default=None, gt=0, le=1, description="Also: share of windows in the reference's ISO zone."
    )
    min_battery_life_years: float | None = Field(
        default=None,
        gt=0,
        strict=True,  # a number, not a string that happens to read as one
        description="Also: the node's battery life, in years, on `battery` at `report_interval`.",
    )
    battery: str = Field(
        default="2xAA", strict=True, description="Cell the life is counted on: 2xAA, C or D."
    )
    report_interval: str = Field(
        default="10min", strict=True, description="One report per interval: 30s, 10min, 1h, 1d."
    )

    @field_validator("battery")
    @classmethod
    def _known_cell(cls, value: str) -> str:
        if value.strip().lower() not in CELLS:
            names = ", ".join(c.name for c in CELLS.values())
            raise ValueError(f"unknown battery {value!r}; choose one of {names}")
        return value

    @field_validator("report_interval")
    @classmethod
    def _duration(cls, value: str) -> str:
        try:
            parse_interval(value)
        except SDTError as exc:
            raise ValueError(str(exc)) from None
        return value

    @model_validator(mode="after")
    def _exactly_one(self) -> Target:
        given = [self.macro_f1, self.fraction_of_reference, self.max_loss, self.max_loss_to_base]
        if sum(v is not None for v in given) != 1:
            raise ValueError(
                "give exactly one of macro_f1, fraction_of_reference, max_loss, max_loss_to_base"
            )
        cap = CELLS[self.battery.strip().lower()]
        wanted = self.min_battery_life_years
        if wanted is not None and wanted > cap.shelf_life_years:
            raise ValueError(
                f"min_battery_life_years = {wanted:g} exceeds the {cap.name} cell's rated "
                f"{cap.shelf_life_years:g}-year shelf life, so no node can meet it; lower it or "
                f"choose another battery (docs/edge.md)"
            )
        return self

    def life_notes(self) -> list[str]:
        """``battery``/``report_interval`` given without a life threshold: what they do then."""
        given = [f for f in ("battery", "report_interval") if f in self.model_fields_set]
        if self.min_battery_life_years is not None or not given:
            return []
        words = " and ".join(f"sweep.target.{f} = {getattr(self, f)!r}" for f in given)
        return [
            f"{words} without min_battery_life_years: sets the battery life shown in "
            f"points.csv, pareto.csv and the front with life only; no point is judged on it "
            f"(add min_battery_life_years to make it a constraint)"
        ]

    @property
    def interval_s(self) -> float:
        """Seconds between reports (``report_interval``)."""
        return parse_interval(self.report_interval)

    def node(self) -> str:
        """The battery and reporting rate the life is counted at, in words."""
        every = re.sub(r"^([\d.]+)", r"\1 ", format_interval(self.interval_s))  # "10 min"
        return f"{self.battery}, a report per {every}"

    def describe(self) -> str:
        """The target in words, for tables and the report."""
        if self.macro_f1 is not None:
            words = f"Macro-F1 >= {self.macro_f1:g}"
        elif self.fraction_of_reference is not None:
            words = f">= {self.fraction_of_reference:g} x reference Macro-F1"
        elif self.max_loss is not None:
            words = f"loss to reference <= {self.max_loss:g}"
        else:
            words = f"loss to base <= {self.max_loss_to_base:g}"
        if self.zone_agreement is not None:
            words += f" and zone agreement >= {self.zone_agreement:g}"
        if self.min_battery_life_years is not None:
            words += f" and battery life >= {self.min_battery_life_years:g} years ({self.node()})"
        return words
