"""A part's supply table: current per mode, standby current, turn-on time, each sourced.

In a part file::

    [supply.measure_ua]
    by = "odr"                     # or "mode,odr": one figure per combination
    table = { "3200" = 140, "1600" = 90 }
    doc = "ds"
    where = "Table 7, Typical Current Consumption vs. Data Rate"
    printed = "3200 1600 1111 140 | 1600 800 1110 90"
    basis = "typical"

    [supply.standby_ua]
    value = 0.1
    doc = "ds"
    where = "page 1, Features"
    printed = "0.1 uA in standby mode at VS = 2.5 V (typical)"

    [supply.turn_on_ms]
    absent = "not in the copy read"

``printed`` is the datasheet's own words (a table's rows joined by " | "):
every figure must appear in it, in the row of its mode where there is a
table, which the catalogue tests check. A mode the table does not cover has
no figure (``absent``), never a neighbour's. :func:`resolve_supply` turns the
table and a mode into the sensor's :class:`~sdt_framework.specs.supply.Supply`.
"""

from __future__ import annotations

from collections.abc import Mapping

from pydantic import Field, model_validator

from ..specs.supply import Supply, SupplyFigure
from .values import Document, Model

__all__ = ["PartFigure", "PartSupply", "resolve_supply"]


class PartFigure(Model):
    """One supply figure of a part: a value, a table over mode keys, or absent."""

    value: float | None = Field(default=None, ge=0)
    by: str | None = Field(default=None, description="Mode key(s), comma-joined, e.g. 'mode,odr'.")
    table: dict[str, float] | None = Field(default=None, description="Figure per option label.")
    columns: list[str] | None = Field(
        default=None,
        description="For a 'mode,odr' table: the printed table's value columns, by option of "
        "the first key (a row is the ODR, then one figure per column).",
    )
    absent: str | None = None
    doc: str | None = Field(default=None, description="Key of the part's [documents].")
    where: str = ""
    printed: str = ""
    printed_unit: str = Field(
        default="", description="Unit of the printed number if not the field's."
    )
    basis: str = ""
    note: str = ""

    @model_validator(mode="after")
    def _check(self) -> PartFigure:
        forms = [self.value is not None, self.table is not None, self.absent is not None]
        if sum(forms) != 1:
            raise ValueError("give exactly one of value, table (with by) or absent")
        if (self.table is None) != (self.by is None):
            raise ValueError("a table needs 'by' (the mode key or keys it is over), and only it")
        if self.absent is None and not (self.doc and self.where and self.printed):
            raise ValueError("a figure needs doc, where and printed (the datasheet's words)")
        return self

    def mode_keys(self) -> list[str]:
        """The mode keys of ``by``."""
        return [k.strip() for k in (self.by or "").split(",") if k.strip()]


class PartSupply(Model):
    """The three supply figures of a part."""

    measure_ua: PartFigure
    standby_ua: PartFigure
    turn_on_ms: PartFigure

    def figures(self) -> dict[str, PartFigure]:
        """The figures by field name."""
        return {
            "measure_ua": self.measure_ua,
            "standby_ua": self.standby_ua,
            "turn_on_ms": self.turn_on_ms,
        }

    def check(self, documents: Mapping[str, Document], modes: Mapping[str, object]) -> None:
        """Every document and mode key named exists (raises ValueError)."""
        for field, figure in self.figures().items():
            if figure.doc is not None and figure.doc not in documents:
                raise ValueError(f"supply.{field}: document {figure.doc!r} is not in [documents]")
            for key in figure.mode_keys():
                if key not in modes:
                    raise ValueError(f"supply.{field}: 'by' names {key!r}, not a mode key")


def _figure(
    figure: PartFigure, documents: Mapping[str, Document], mode: Mapping[str, str]
) -> SupplyFigure:
    if figure.absent is not None:
        return SupplyFigure(absent=figure.absent, note=figure.note)
    document = documents[figure.doc or ""]
    cite = dict(
        doc=f"{document.title}, {document.revision}",
        where=figure.where,
        printed=figure.printed,
        printed_unit=figure.printed_unit,
        basis=figure.basis,
        note=figure.note,
    )
    if figure.table is None:
        return SupplyFigure(value=figure.value, **cite)
    label = ",".join(mode.get(key, "") for key in figure.mode_keys())
    if label not in figure.table:
        return SupplyFigure(
            absent=f"{figure.where} gives no figure for {figure.by} = {label}", note=figure.note
        )
    return SupplyFigure(value=figure.table[label], **cite)


def resolve_supply(
    supply: PartSupply, documents: Mapping[str, Document], mode: Mapping[str, str]
) -> Supply:
    """The part's supply figures in ``mode`` (every mode key with its option)."""
    label = ",".join(f"{k}={v}" for k, v in sorted(mode.items()))
    return Supply(
        measure_ua=_figure(supply.measure_ua, documents, mode),
        standby_ua=_figure(supply.standby_ua, documents, mode),
        turn_on_ms=_figure(supply.turn_on_ms, documents, mode),
        mode=label,
    )
