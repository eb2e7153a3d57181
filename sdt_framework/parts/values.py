"""The sourced values of a part: documents, prices, and one value with its provenance.

An :class:`Entry` is one number (or "none", a per-axis triple, a fraction of
the output data rate, a table over another mode key's options) together with
the document, table or page and basis it comes from; or the record that the
documents lack it, with the stand-in used and why.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

__all__ = ["AxisValues", "Basis", "Document", "Entry", "Model", "NoPrice", "Price"]

Basis = Literal["typical", "minimum", "maximum", "nominal", "setting", "derived"]


class Model(BaseModel):
    """Frozen, unknown fields rejected."""

    model_config = ConfigDict(frozen=True, extra="forbid")


class Document(Model):
    """A source document: title, revision, where to find it."""

    title: str = Field(min_length=1, description="Document title as printed.")
    revision: str = Field(min_length=1, description="Revision and date as printed.")
    url: str = Field(default="", description="Where the document is published.")
    secondary: bool = Field(
        default=False, description="True for a source quoting the datasheet (forum, driver)."
    )
    note: str = Field(default="", description="How it was read, caveats.")


class Price(Model):
    """An indicative unit price: what one unit cost, where and when."""

    amount: float = Field(gt=0, description="Price of one unit.")
    currency: str = Field(pattern=r"^[A-Z]{3}$", description="ISO 4217 code, e.g. EUR.")
    quantity: str = Field(min_length=1, description="Order quantity the price is for.")
    source: str = Field(min_length=1, description="Vendor page the price was read from.")
    date: str = Field(min_length=1, description="When the price was read (as known).")
    note: str = Field(default="", description="Variant ordered, caveats.")


class NoPrice(Model):
    """The record that no public unit price was found: every search made, and when.

    A part file says so in ``[no_price]`` instead of leaving ``[price]`` out,
    so a missing price reads as searched-for, never as forgotten; nothing is
    filled in.
    """

    searched: tuple[str, ...] = Field(
        min_length=1, description="Each search made: where (site, corpus) and what was asked."
    )
    date: str = Field(min_length=1, description="When the searches were made.")
    note: str = Field(default="", description="Near misses (other variants, sibling parts).")


class AxisValues(Model):
    """One value per axis."""

    x: float = Field(ge=0)
    y: float = Field(ge=0)
    z: float = Field(ge=0)


class Entry(Model):
    """One value with its provenance, or the record that the documents lack it.

    Exactly one form: ``value`` (a number, or "none" for a stage the part does
    not have), ``axes`` (x, y, z), ``odr_fraction`` (times the output data
    rate) or ``by`` + ``table`` (the value per option of another mode key).
    Or ``absent`` (what the documents lack) with ``stand_in`` (an Entry or
    "none") and ``why`` that stand-in.
    """

    value: float | Literal["none"] | None = None
    axes: AxisValues | None = None
    odr_fraction: float | None = Field(default=None, gt=0, le=0.5)
    by: str | None = None
    table: dict[str, float | AxisValues] | None = None
    doc: str | None = Field(default=None, description="Id of a document of the part.")
    where: str = Field(default="", description="Table, page or section.")
    basis: Basis | None = Field(default=None, description="typical, maximum, setting...")
    note: str = ""
    absent: str | None = Field(default=None, description="What the documents do not give.")
    stand_in: Entry | Literal["none"] | None = None
    why: str = Field(default="", description="Why this stand-in.")

    @property
    def form(self) -> str:
        """Which form this entry has: value, axes, odr_fraction, by or absent."""
        if self.absent is not None:
            return "absent"
        return next(
            f for f in ("value", "axes", "odr_fraction", "by") if getattr(self, f) is not None
        )

    @model_validator(mode="after")
    def _one_form(self) -> Entry:
        forms = [f for f in ("value", "axes", "odr_fraction", "by") if getattr(self, f) is not None]
        if self.absent is not None:
            if forms:
                raise ValueError(f"an absent value cannot also give {forms[0]}")
            if self.stand_in is None or not self.why:
                raise ValueError("an absent value needs stand_in and why")
            if isinstance(self.stand_in, Entry) and self.stand_in.absent is not None:
                raise ValueError("a stand-in cannot itself be absent")
            return self
        if len(forms) != 1:
            raise ValueError("give exactly one of value, axes, odr_fraction, by (or absent)")
        if (self.by is None) != (self.table is None):
            raise ValueError("'by' and 'table' go together")
        if self.stand_in is not None or self.why:
            raise ValueError("stand_in and why belong to an absent value")
        if not self.doc or not self.where or self.basis is None:
            raise ValueError("a value needs its provenance: doc, where and basis")
        return self

    def documents(self) -> list[str]:
        """Ids of the documents this entry cites (its stand-in's included)."""
        ids = [self.doc] if self.doc else []
        if isinstance(self.stand_in, Entry):
            ids += self.stand_in.documents()
        return ids

    def forms(self) -> set[str]:
        """The forms of this entry and of its stand-in."""
        own = {self.form}
        if isinstance(self.stand_in, Entry):
            own |= self.stand_in.forms()
        elif self.stand_in == "none":
            own.add("none")
        if self.value == "none":
            own.add("none")
        return own
