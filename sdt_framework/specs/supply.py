"""What an accelerometer draws from its supply: measuring, asleep, and how long it takes to wake.

A :class:`Supply` belongs to one sensor in one mode (a part's supply table is
resolved to it by :mod:`sdt_framework.parts.supply`). Each figure is a
:class:`SupplyFigure`: the number with the document, revision, table or page
and the datasheet's own printed words, or the record that the documents read
do not give it (``absent``, with why). The supply does not change what the
chain computes, so it is left out of a sensor's content hash.
"""

from __future__ import annotations

import math
import re

from pydantic import BaseModel, ConfigDict, Field, model_validator

from ..errors import shown

__all__ = ["Supply", "SupplyFigure", "printed_numbers"]

_NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])")


def printed_numbers(text: str) -> list[float]:
    """Every plain number in ``text`` ("140", "0.1"), in order: what a datasheet quote states."""
    return [float(match) for match in _NUMBER.findall(text)]


class SupplyFigure(BaseModel):
    """One supply figure with its provenance, or why the documents give none.

    ``value`` is in the unit the field names (uA for currents, ms for times).
    ``printed`` quotes the datasheet's own row or sentence; the number must be
    in it, which the catalogue tests check for every figure.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    value: float | None = Field(default=None, description="The figure, in the field's unit.")
    absent: str | None = Field(default=None, description="Why there is no figure.")
    doc: str = Field(default="", description="Document title and revision.")
    where: str = Field(default="", description="Table, page or section.")
    printed: str = Field(default="", description="The datasheet's words holding the number.")
    printed_unit: str = Field(
        default="", description="Unit of the printed number when not the field's (mA, nA)."
    )
    basis: str = Field(default="", description="typical, maximum, ... as the document says.")
    note: str = Field(default="", description="Conditions (supply voltage, mode), caveats.")

    @model_validator(mode="after")
    def _check(self) -> SupplyFigure:
        if (self.value is None) == (self.absent is None):
            raise ValueError("give exactly one of value or absent")
        if self.value is not None:
            if not (math.isfinite(self.value) and self.value >= 0):
                raise ValueError(f"value must be a finite number >= 0, got {shown(self.value)}")
            if not (self.doc and self.where and self.printed):
                raise ValueError("a value needs doc, where and printed (the datasheet's words)")
        return self

    def cited(self) -> str:
        """``"<doc>, <where>"``, or why the figure is absent."""
        if self.value is None:
            return f"not given: {self.absent}"
        return f"{self.doc}, {self.where}"


class Supply(BaseModel):
    """Supply current while measuring and in standby, and the turn-on time, each sourced."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    measure_ua: SupplyFigure = Field(description="Supply current while measuring, uA.")
    standby_ua: SupplyFigure = Field(description="Supply current in standby/power-down, uA.")
    turn_on_ms: SupplyFigure = Field(description="Time from standby to valid data, ms.")
    mode: str = Field(default="", description="The operating mode the figures belong to.")

    def figures(self) -> dict[str, SupplyFigure]:
        """The three figures by field name."""
        return {
            "measure_ua": self.measure_ua,
            "standby_ua": self.standby_ua,
            "turn_on_ms": self.turn_on_ms,
        }
