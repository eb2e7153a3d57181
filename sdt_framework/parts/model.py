"""A real part as data: chain values with per-value provenance, and its operating modes.

A :class:`PartSpec` is what a datasheet says about one accelerometer, in the
units of the SDT chain. Every value is an :class:`Entry` that names the
document, the table or page and whether the figure is typical, minimum,
maximum, nominal or a register setting; a figure the documents do not give is
an Entry with ``absent`` (why) and the ``stand_in`` used instead (and why that
one). Operating modes (:class:`Mode`: range, output data rate, filter setting)
choose among options, each of which may set chain values; a filter corner the
datasheet gives as a fraction of the output data rate is stored as
``odr_fraction`` so that choosing another rate moves it.

The model checks the structure once, when a part is registered: every chain
value is determined for every mode, every document exists, a value is set by
at most one mode key. :mod:`sdt_framework.parts.resolve` turns a part and a
mode into a :class:`~sdt_framework.specs.SensorSpec`. A part's datasheet error
terms (``[errors.<term>]``, :mod:`sdt_framework.parts.error_terms`) stay off unless
the mode enables them.
"""

from __future__ import annotations

import re
from typing import Any, ClassVar, Literal

from pydantic import Field, field_validator, model_validator

from ..specs import Spec
from .error_terms import ErrorTerm, check_terms
from .sampling import PartSampling
from .supply import PartSupply
from .values import AxisValues, Basis, Document, Entry, Model, NoPrice, Price

__all__ = [
    "CHAIN_VALUES",
    "AxisValues",
    "Document",
    "Entry",
    "Mode",
    "NoPrice",
    "PartSpec",
    "Price",
]

#: SensorSpec fields a part must determine for every mode
CHAIN_VALUES = (
    "sampling_rate_hz",
    "full_scale_g",
    "adc_bits",
    "noise_density_ug_rthz",
    "mech_cutoff_hz",
    "analog_cutoff_hz",
    "digital_cutoff_hz",
    "digital_order",
)
#: fields a part may set but need not (the chain model's orders, SPEC section 2)
OPTIONAL_VALUES = ("mech_order", "analog_order")
CUTOFFS = ("mech_cutoff_hz", "analog_cutoff_hz", "digital_cutoff_hz")
#: fields that may have a value per axis
PER_AXIS = ("noise_density_ug_rthz", "mech_cutoff_hz")
#: fields that may be "none" (the stage is not part of the chain)
MAY_BE_NONE = (*CUTOFFS, "digital_order")

_KEY = re.compile(r"^[a-z][a-z0-9_]*$")
_LABEL = re.compile(r"^[a-z0-9][a-z0-9._+-]*$")


class Mode(Model):
    """One mode key (e.g. range): its options, its default and why that default.

    With ``field``, each option's label is that field's value (``unit``
    stripped: option "8g" of range sets full_scale_g = 8), cited by ``doc``,
    ``where`` and ``basis``. An option may set further values. ``only_with``
    restricts an option to some options of another key.
    """

    default: str
    default_why: str = Field(min_length=1, description="Why this is the default option.")
    field: str | None = None
    unit: str = ""
    doc: str | None = None
    where: str = ""
    basis: Basis | None = None
    options: dict[str, dict[str, Entry]]
    only_with: dict[str, dict[str, list[str]]] = Field(default_factory=dict)

    @field_validator("options", mode="before")
    @classmethod
    def _list_of_labels(cls, value: Any) -> Any:
        if isinstance(value, list):
            return {str(label): {} for label in value}
        return value

    @model_validator(mode="after")
    def _check(self) -> Mode:
        if not self.options:
            raise ValueError("a mode needs at least one option")
        for label in self.options:
            if not _LABEL.match(label):
                raise ValueError(f"option {label!r}: use lower-case letters, digits, '.', '+', '-'")
        if self.default not in self.options:
            raise ValueError(f"default {self.default!r} is not one of {list(self.options)}")
        if self.field is not None:
            if not self.doc or not self.where or self.basis is None:
                raise ValueError("a mode with 'field' needs doc, where and basis")
            for label in self.options:
                self.label_value(label)
        for label in self.only_with:
            if label not in self.options:
                raise ValueError(f"only_with names {label!r}, not an option")
        return self

    def label_value(self, label: str) -> float:
        """The number an option's label stands for (its unit stripped)."""
        text = label[: -len(self.unit)] if self.unit and label.endswith(self.unit) else label
        try:
            return float(text)
        except ValueError:
            raise ValueError(
                f"option {label!r} is not a number in {self.unit or 'the field unit'}"
            ) from None

    def entries(self, label: str) -> dict[str, Entry]:
        """The values option ``label`` sets, the label's own value included."""
        own = dict(self.options[label])
        if self.field is not None and self.field not in own:
            own[self.field] = Entry(
                value=self.label_value(label), doc=self.doc, where=self.where, basis=self.basis
            )
        return own


class PartSpec(Spec):
    """A real accelerometer: documents, sourced chain values, operating modes, price."""

    kind: ClassVar[str] = "part"

    manufacturer: str = Field(min_length=1)
    interface: Literal["digital", "analog"]
    documents: dict[str, Document] = Field(min_length=1)
    values: dict[str, Entry] = Field(default_factory=dict, description="Values of every mode.")
    modes: dict[str, Mode] = Field(default_factory=dict)
    price: Price | None = None
    no_price: NoPrice | None = Field(
        default=None, description="No public price found: what was searched, when ([no_price])."
    )
    notes: tuple[str, ...] = Field(default=(), description="Caveats a user should know.")
    errors: dict[str, ErrorTerm] = Field(
        default_factory=dict,
        description="Datasheet error terms (offset_tempco, sensitivity_tempco, nonlinearity, "
        "cross_axis); off unless a mode enables them (sdt_framework.parts.error_terms).",
    )
    supply: PartSupply | None = Field(
        default=None,
        description="Supply current per mode, standby current, turn-on time "
        "(sdt_framework.parts.supply); not hashed: the chain does not depend on it.",
    )
    sampling: PartSampling | None = Field(
        default=None,
        description="How the part reaches its output rate, sourced ([sampling], "
        "sdt_framework.parts.sampling); none: the paper's sample-then-filter model.",
    )

    @model_validator(mode="after")
    def _check_structure(self) -> PartSpec:
        if self.price is not None and self.no_price is not None:
            raise ValueError("give [price] or [no_price] (none found), not both")
        for key in self.modes:
            if not _KEY.match(key):
                raise ValueError(f"mode key {key!r}: use lower-case letters, digits and '_'")
        setters: dict[str, list[str]] = {}
        for key, mode in self.modes.items():
            for label in mode.options:
                for field, entry in mode.entries(label).items():
                    self._check_entry(field, entry, f"modes.{key}.options.{label}.{field}", key)
                    if key not in setters.setdefault(field, []):
                        setters[field].append(key)
            for label, rules in mode.only_with.items():
                for other, allowed in rules.items():
                    if other not in self.modes or other == key:
                        raise ValueError(f"modes.{key}.only_with.{label}: no other key {other!r}")
                    bad = sorted(set(allowed) - set(self.modes[other].options))
                    if bad:
                        raise ValueError(f"modes.{key}.only_with.{label}: {other} has no {bad}")
        for field, entry in self.values.items():
            self._check_entry(field, entry, f"values.{field}", None)
        check_terms(self.errors, self.documents, self.modes)
        if self.supply is not None:
            self.supply.check(self.documents, self.modes)
        if self.sampling is not None and self.sampling.doc not in self.documents:
            raise ValueError(f"sampling: document {self.sampling.doc!r} is not in [documents]")
        for field in CHAIN_VALUES:
            keys = setters.get(field, [])
            if len(keys) > 1:
                raise ValueError(f"{field} is set by two mode keys ({', '.join(keys)}); use 'by'")
            complete = keys and all(
                field in self.modes[keys[0]].entries(o) for o in self._opts(keys[0])
            )
            if not complete and field not in self.values:
                raise ValueError(
                    f"{field} is not given for every mode: give it in [values] (or mark it "
                    f"absent with a stand_in and why)"
                )
        return self

    def _opts(self, key: str) -> list[str]:
        return list(self.modes[key].options)

    def _check_entry(self, field: str, entry: Entry, where: str, key: str | None) -> None:
        if field not in CHAIN_VALUES and field not in OPTIONAL_VALUES:
            raise ValueError(f"{where}: unknown value {field!r}; known: {', '.join(CHAIN_VALUES)}")
        for doc in entry.documents():
            if doc not in self.documents:
                raise ValueError(f"{where}: document {doc!r} is not in [documents]")
        forms = entry.forms()
        if "odr_fraction" in forms and field not in CUTOFFS:
            raise ValueError(f"{where}: only a filter cutoff can be a fraction of the ODR")
        if "axes" in forms and field not in PER_AXIS:
            raise ValueError(f"{where}: only {', '.join(PER_AXIS)} may differ per axis")
        if "none" in forms and field not in MAY_BE_NONE:
            raise ValueError(f"{where}: only a filter stage may be 'none'")
        for sub in (entry, entry.stand_in):
            if isinstance(sub, Entry) and sub.by is not None:
                if sub.by not in self.modes or sub.by == key:
                    raise ValueError(f"{where}: 'by' must name another mode key, got {sub.by!r}")
                if set(sub.table or {}) != set(self.modes[sub.by].options):
                    raise ValueError(
                        f"{where}: table must give every option of {sub.by} "
                        f"({', '.join(self.modes[sub.by].options)})"
                    )
                if any(isinstance(v, AxisValues) for v in (sub.table or {}).values()) and (
                    field not in PER_AXIS
                ):
                    raise ValueError(f"{where}: only {', '.join(PER_AXIS)} may differ per axis")

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields; a part without error terms hashes as before they existed."""
        data = super().content_dict()
        for key in ("errors", "sampling"):  # parts without them hash as before they existed
            if not data.get(key):
                data.pop(key, None)
        data.pop("supply", None)  # the node's energy, not the chain
        return data

    def default_mode(self) -> dict[str, str]:
        """Every mode key with its default option."""
        return {key: mode.default for key, mode in sorted(self.modes.items())}
