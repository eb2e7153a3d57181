"""A figure with where it comes from, and the reading of the edge package's TOML data files.

Every current, capacity, self-discharge and shelf life the node model uses is
a :class:`Figure` in one of the data files beside this module (``cells.toml``,
``radios.toml``, ``node.toml``): the value in the unit its field names, the
document and revision, the table, page or figure, and the document's own
printed words holding the number (``printed``). The tests check that the
number is in those words for every figure, as the sensor catalogue does for
its supply figures (:mod:`sdt_framework.specs.supply`).
"""

from __future__ import annotations

import math
from importlib import resources
from typing import Any, TypeVar

from pydantic import BaseModel, ConfigDict, Field, model_validator

from ..errors import shown
from ..toml_files import parse_toml, validate_file

__all__ = ["DataModel", "Figure", "read_data"]

M = TypeVar("M", bound=BaseModel)


class DataModel(BaseModel):
    """The data files' models: unknown keys and inf/nan are refused, values frozen."""

    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class Figure(DataModel):
    """One number with its provenance.

    ``printed`` quotes the document's row or sentence; ``printed_unit`` is the
    unit the number is printed in when it is not the field's (Ah for mAh, nA
    for uA), so a test can find the value in the quote.
    """

    value: float = Field(description="The figure, in the unit its field names.")
    doc: str = Field(min_length=1, description="Document, revision, date.")
    where: str = Field(min_length=1, description="Table, figure, page or section.")
    printed: str = Field(min_length=1, description="The document's words holding the number.")
    printed_unit: str = Field(default="", description="Unit printed, if not the field's.")
    basis: str = Field(default="typical", description="typical, maximum, bound, assumption ...")
    note: str = Field(default="", description="Conditions, caveats, secondary source.")

    @model_validator(mode="after")
    def _finite(self) -> Figure:
        if not (math.isfinite(self.value) and self.value >= 0):
            raise ValueError(f"value must be a finite number >= 0, got {shown(self.value)}")
        return self

    def cited(self) -> str:
        """``"<doc>, <where>"`` (and the basis when it is not typical)."""
        basis = "" if self.basis == "typical" else f" ({self.basis})"
        return f"{self.doc}, {self.where}{basis}"


def read_data(name: str, model: type[M]) -> M:
    """The package data file ``name`` (beside this module) validated as ``model``.

    A fault here is a fault of the installed package, named with the file.
    """
    text = resources.files(__package__).joinpath(name).read_text(encoding="utf-8")
    data: Any = parse_toml(text, name)
    return validate_file(model, data, name)
