"""A part's datasheet error terms, as data: the figure, its provenance, or why it is absent.

Four terms, each carried into the chain by one parameter of a built-in stage
(``plugins/stages``): the 0 g offset temperature coefficient (``offset``
stage), the sensitivity temperature coefficient (``scale``), the amplitude
nonlinearity (``nonlinearity``) and the cross-axis sensitivity
(``cross-axis``). An :class:`ErrorTerm` holds the datasheet's ± figure
converted to that parameter's unit, where it was read, whether it is a typical
or a maximum figure, and the figure as printed; or the record that the
documents lack it (``absent``), with a stand-in from another document or
``"none"``. A figure that depends on another mode key (the nonlinearity per
range) is a ``table`` over that key's options; options it leaves out are
absent in those modes.

:mod:`sdt_framework.parts.error_modes` turns the terms into per-unit
tolerances when a user enables them (``adxl355[errors=datasheet]``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

from pydantic import Field, model_validator

from .values import AxisValues, Document, Model

__all__ = ["TERMS", "ErrorTerm", "TermKind", "check_terms"]

#: temperature of the datasheets' figures and of the stages' nominal values, deg C
REFERENCE_C = 25.0


@dataclass(frozen=True)
class TermKind:
    """How one error term enters the chain: a stage parameter, scaled by ``factor``."""

    stage: str
    param: str
    unit: str
    factor: float  # the parameter's per-unit spread = factor x the datasheet figure
    title: str
    temperature: bool  # acts only away from the reference temperature


#: the error terms a part may give, in the order they are listed and applied
TERMS: dict[str, TermKind] = {
    "offset_tempco": TermKind(
        "offset", "tempco_mg_per_c", "mg/°C", 1.0, "0 g offset temperature coefficient", True
    ),
    "sensitivity_tempco": TermKind(
        "scale", "tempco_pct_per_c", "%/°C", 1.0, "sensitivity temperature coefficient", True
    ),
    # A datasheet's nonlinearity is the largest deviation from the best-fit
    # (least-squares) straight line over +-FS, in % FS. A pure second-order
    # term k2 a^2 deviates from its best-fit line by 2/3 of its value at full
    # scale, so the stage's second_pct_fs (the term at full scale) is 3/2 x it.
    "nonlinearity": TermKind(
        "nonlinearity", "second_pct_fs", "% FS", 1.5, "nonlinearity (best-fit line)", False
    ),
    "cross_axis": TermKind("cross-axis", "pct", "%", 1.0, "cross-axis sensitivity", False),
}


class ErrorTerm(Model):
    """One error term of a part: a ± figure with its provenance, or why it is absent.

    Exactly one form: ``value`` (all axes), ``axes`` (x, y, z) or ``by`` +
    ``table`` (per option of another mode key; options left out of the table
    are absent there, and ``absent`` says why). Or ``absent`` alone (the
    documents lack the term) with ``stand_in`` (an ErrorTerm from another
    document, or "none") and ``why``. Figures are half-widths in the stage
    parameter's unit (:data:`TERMS`); ``printed`` is the row as the document
    prints it, ``note`` the conversion and conditions, ``range_c`` the
    temperature range the document states for a temperature coefficient.
    """

    value: float | None = Field(default=None, gt=0)
    axes: AxisValues | None = None
    by: str | None = None
    table: dict[str, float] | None = None
    doc: str | None = Field(default=None, description="Id of a document of the part.")
    where: str = Field(default="", description="Table, page or section.")
    basis: Literal["typical", "maximum"] | None = None
    printed: str = Field(default="", description="The figure as the document prints it.")
    range_c: tuple[float, float] | None = Field(
        default=None, description="Temperature range the document states for it, deg C."
    )
    note: str = Field(default="", description="Conversion to the stage's unit, conditions.")
    absent: str | None = Field(default=None, description="What the documents do not give.")
    stand_in: ErrorTerm | Literal["none"] | None = None
    why: str = Field(default="", description="Why this stand-in.")

    @model_validator(mode="after")
    def _one_form(self) -> ErrorTerm:
        forms = [f for f in ("value", "axes", "by") if getattr(self, f) is not None]
        if not forms:
            if self.absent is None:
                raise ValueError("give one of value, axes, by (or absent)")
            if self.stand_in is None or not self.why:
                raise ValueError("an absent term needs stand_in (a term or 'none') and why")
            if isinstance(self.stand_in, ErrorTerm) and self.stand_in.stand_in is not None:
                raise ValueError("a stand-in cannot itself be absent")
            return self
        if len(forms) > 1:
            raise ValueError(f"give one of value, axes, by, not {' and '.join(forms)}")
        if (self.by is None) != (self.table is None):
            raise ValueError("'by' and 'table' go together")
        if self.absent is not None and self.by is None:
            raise ValueError("'absent' with a figure names the options a 'table' leaves out")
        if self.stand_in is not None or self.why:
            raise ValueError("stand_in and why belong to an absent term")
        if not self.doc or not self.where or self.basis is None or not self.printed:
            raise ValueError("a figure needs its provenance: doc, where, basis and printed")
        if any(v <= 0 for v in (self.table or {}).values()):
            raise ValueError("table figures must be positive")
        if self.range_c is not None and not self.range_c[0] <= REFERENCE_C <= self.range_c[1]:
            raise ValueError("range_c must run from its low end to its high end over 25 °C")
        return self

    @property
    def cited(self) -> ErrorTerm | None:
        """The term whose figure is used: itself, its stand-in, or None."""
        if self.value is not None or self.axes is not None or self.by is not None:
            return self
        return self.stand_in if isinstance(self.stand_in, ErrorTerm) else None

    def figure(self, mode: Mapping[str, str]) -> AxisValues | None:
        """The figure on each axis in ``mode`` (stand-in included), or None where absent."""
        term = self.cited
        if term is None:
            return None
        if term.axes is not None:
            return term.axes
        value = term.value if term.by is None else (term.table or {}).get(mode[term.by])
        return None if value is None else AxisValues(x=value, y=value, z=value)


def check_terms(
    terms: Mapping[str, ErrorTerm], documents: Mapping[str, Document], modes: Mapping[str, object]
) -> None:
    """Raise ValueError (naming the field) if a term is unknown or cites what the part lacks."""
    for name, term in terms.items():
        if name not in TERMS:
            raise ValueError(f"errors.{name}: unknown error term; known: {', '.join(TERMS)}")
        for sub in (term, term.stand_in):
            if not isinstance(sub, ErrorTerm):
                continue
            where = f"errors.{name}" + (".stand_in" if sub is not term else "")
            if sub.doc is not None and sub.doc not in documents:
                raise ValueError(f"{where}: document {sub.doc!r} is not in [documents]")
            if sub.range_c is not None and not TERMS[name].temperature:
                raise ValueError(f"{where}: range_c belongs to a temperature coefficient")
            if sub.by is None:
                continue
            options = getattr(modes.get(sub.by), "options", None)
            if options is None:
                raise ValueError(f"{where}: 'by' must name a mode key, got {sub.by!r}")
            extra = sorted(set(sub.table or {}) - set(options))
            if extra:
                raise ValueError(f"{where}: {sub.by} has no option {', '.join(extra)}")
            if (set(sub.table or {}) != set(options)) != (sub.absent is not None):
                raise ValueError(
                    f"{where}: a table that leaves out options of {sub.by} says why in 'absent' "
                    f"(and only then)"
                )
