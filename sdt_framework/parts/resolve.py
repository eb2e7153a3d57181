"""A part in one mode: the checked choice of options, the SensorSpec, the provenance.

:func:`select_mode` checks a user's choice (unknown key, option not allowed,
option not allowed with another) and fills in defaults; :func:`resolve`
evaluates every chain value for that mode (fractions of the output data rate
times the rate, per-option tables, stand-ins) and returns the
:class:`~sdt_framework.specs.SensorSpec` named in canonical form together
with one :class:`FieldSource` per value saying where it came from. The
error-term keys (``errors``, ``cross_axis``, ``temp``) are split off first and
handled by :mod:`sdt_framework.parts.error_modes`: off by default, left out of
the name at their defaults.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from dataclasses import field as _field
from itertools import product

from pydantic import ValidationError

from ..errors import SDTError, field_errors
from ..specs import SensorSpec
from ..specs.sensor import PAPER_SAMPLING
from ..specs.stage_use import StageUse, Tolerance
from .error_modes import (
    ERROR_KEYS,
    TermSource,
    error_stages,
    shown_keys,
    split_error_keys,
    term_sources,
)
from .model import CHAIN_VALUES, OPTIONAL_VALUES, AxisValues, Entry, PartSpec
from .names import canonical_name
from .supply import resolve_supply

__all__ = ["FieldSource", "ModeError", "Resolved", "all_modes", "resolve", "select_mode"]

#: the chain model's filter orders (SPEC section 2) when a part does not give its own
MODEL_ORDERS = {"mech_order": 2, "analog_order": 1}
NOT_DOCUMENTS = ("", "chain model")
INTEGERS = ("adc_bits", "digital_order", "mech_order", "analog_order")


class ModeError(SDTError):
    """A mode a part does not have: names the part, the key and the allowed options."""


@dataclass(frozen=True)
class FieldSource:
    """Where one value of a resolved part comes from."""

    field: str
    value: float | int | str | dict[str, float] | None
    source: str  # document title and revision, or "chain model"
    where: str
    basis: str
    set_by: str  # "part" or the mode option, e.g. "range=8g"
    absent: str = ""  # what the documents lack (then value is the stand-in)
    why: str = ""
    note: str = ""
    doc: str = ""  # the document's id in the part (``[documents.<id>]``)
    odr_fraction: float | None = None  # the value is this fraction of the output data rate

    def as_dict(self) -> dict[str, object]:
        """JSON-ready view."""
        return dict(self.__dict__)


@dataclass(frozen=True)
class Resolved:
    """A part in one mode: its sensor profile and the provenance of every value."""

    part: PartSpec
    mode: dict[str, str]
    sensor: SensorSpec
    sources: tuple[FieldSource, ...]
    error_mode: dict[str, str] = _field(default_factory=lambda: dict(ERROR_KEYS))
    terms: tuple[TermSource, ...] = ()


def select_mode(part: PartSpec, given: Mapping[str, str]) -> dict[str, str]:
    """The full mode: ``given`` checked against the part, defaults filled in."""
    keys = ", ".join(sorted([*part.modes, *(ERROR_KEYS if part.errors else ())])) or "none"
    for key, option in given.items():
        if key not in part.modes:
            raise ModeError(f"part {part.name!r} has no mode key {key!r}; its keys: {keys}")
        allowed = part.modes[key].options
        if option not in allowed:
            raise ModeError(
                f"part {part.name!r}: {key}={option} is not an option; "
                f"{key} is one of {', '.join(allowed)}"
            )
    mode = {**part.default_mode(), **given}
    for key in sorted(mode):
        rules = part.modes[key].only_with.get(mode[key], {})
        for other, allowed in sorted(rules.items()):
            if mode[other] not in allowed:
                raise ModeError(
                    f"part {part.name!r}: {key}={mode[key]} needs {other} in "
                    f"{', '.join(allowed)}; got {other}={mode[other]}"
                )
    return mode


def all_modes(part: PartSpec) -> list[dict[str, str]]:
    """Every valid mode of ``part`` (the options' product minus only_with exclusions)."""
    keys = sorted(part.modes)
    valid = []
    for options in product(*(part.modes[k].options for k in keys)):
        mode = dict(zip(keys, options, strict=True))
        try:
            valid.append(select_mode(part, mode))
        except ModeError:
            continue
    return valid


def _entries(part: PartSpec, mode: dict[str, str]) -> dict[str, tuple[Entry, str]]:
    chosen = {field: (entry, "part") for field, entry in part.values.items()}
    for key in sorted(mode):
        for field, entry in part.modes[key].entries(mode[key]).items():
            chosen[field] = (entry, f"{key}={mode[key]}")
    return chosen


def _number(entry: Entry, mode: dict[str, str], odr: float | None):
    """The value of a non-absent entry: float, AxisValues or None ('none')."""
    if entry.value is not None:
        return None if entry.value == "none" else float(entry.value)
    if entry.axes is not None:
        return entry.axes
    if entry.odr_fraction is not None:
        if odr is None:
            raise ValueError("the output data rate cannot itself be a fraction of the ODR")
        return entry.odr_fraction * odr
    return (entry.table or {})[mode[entry.by or ""]]


def _evaluate(part: PartSpec, field: str, entry: Entry, set_by: str, mode, odr):
    cited = entry
    if entry.absent is not None:
        if entry.stand_in == "none" or entry.stand_in is None:
            number, cited = None, None
        else:
            cited = entry.stand_in
            number = _number(cited, mode, odr)
    else:
        number = _number(entry, mode, odr)
    shown = number.model_dump() if isinstance(number, AxisValues) else number
    if field in INTEGERS and isinstance(shown, float):
        shown = int(shown)
    doc = part.documents[cited.doc] if cited is not None and cited.doc else None
    source = (
        f"{doc.title}, {doc.revision}" + (" (secondary)" if doc.secondary else "") if doc else ""
    )
    fs = FieldSource(
        field,
        shown,
        source,
        cited.where if cited is not None else "",
        (cited.basis or "") if cited is not None else "",
        set_by,
        entry.absent or "",
        entry.why,
        "; ".join(dict.fromkeys(n for n in (entry.note, cited.note if cited else "") if n)),
        cited.doc or "" if cited is not None else "",
        cited.odr_fraction if cited is not None else None,
    )
    return number, fs


def resolve(part: PartSpec, given: Mapping[str, str] | None = None) -> Resolved:
    """``part`` in the mode ``given`` (defaults for the rest) as a checked SensorSpec."""
    chain_given, choice = split_error_keys(part, dict(given or {}))
    mode = select_mode(part, chain_given)
    entries = _entries(part, mode)
    numbers: dict[str, object] = {}
    sources: list[FieldSource] = []
    odr_entry, odr_by = entries["sampling_rate_hz"]
    odr, fs = _evaluate(part, "sampling_rate_hz", odr_entry, odr_by, mode, None)
    numbers["sampling_rate_hz"] = odr
    sources.append(fs)
    for field in (*CHAIN_VALUES[1:], *OPTIONAL_VALUES):
        if field not in entries:  # only the model's orders may be missing
            numbers[field] = MODEL_ORDERS[field]
            sources.append(
                FieldSource(field, MODEL_ORDERS[field], "chain model", "docs/chain.md", "model", "")
            )
            continue
        entry, set_by = entries[field]
        numbers[field], fs = _evaluate(part, field, entry, set_by, mode, odr)
        sources.append(fs)
    if numbers["digital_cutoff_hz"] is None:  # no digital stage: its order follows the cutoff
        numbers["digital_order"] = None
        cutoff = next(s for s in sources if s.field == "digital_cutoff_hz")
        at = next(i for i, s in enumerate(sources) if s.field == "digital_order")
        sources[at] = replace(cutoff, field="digital_order", note="no digital stage in this mode")
    cited = "; ".join(dict.fromkeys(s.source for s in sources if s.source not in NOT_DOCUMENTS))
    # after ``cited``: the sensor's source line (hashed) stays that of its values
    numbers["sampling"], sampled = _sampling(part, numbers["digital_cutoff_hz"])
    sources.append(sampled)
    terms = term_sources(part, mode, choice)
    stages, tolerances = error_stages(terms, choice)
    named = {**mode, **shown_keys(choice)}
    sensor = _sensor(part, named, numbers, cited, stages, tolerances)
    if part.supply is not None:
        supply = resolve_supply(part.supply, part.documents, mode)
        sensor = sensor.model_copy(update={"supply": supply})
    return Resolved(part, mode, sensor, tuple(sources), choice, terms)


def _sampling(part: PartSpec, digital_cutoff: object) -> tuple[str, FieldSource]:
    """The part's sampling model and its provenance (the paper's when it states none)."""
    given = part.sampling
    if given is None:
        return PAPER_SAMPLING, FieldSource(
            "sampling", PAPER_SAMPLING, "chain model", "docs/chain.md", "model", "",
            note="the paper's model: samples at the output rate, digital low-pass after",
        )  # fmt: skip
    doc = part.documents[given.doc]
    notes = [n for n in (given.stopband and f"stopband: {given.stopband}",
                         given.stopband_model and f"modelled as {given.stopband_model}",
                         given.note) if n]  # fmt: skip
    model = given.model
    if model == "decimate" and digital_cutoff is None:
        model = PAPER_SAMPLING
        notes.insert(0, "no digital low-pass in this mode, so no decimation filter to model")
    source = f"{doc.title}, {doc.revision}" + (" (secondary)" if doc.secondary else "")
    fs = FieldSource("sampling", model, source, given.where, given.basis, "part",
                     note="; ".join(notes), doc=given.doc)  # fmt: skip
    return model, fs


def _sensor(
    part: PartSpec,
    mode: dict[str, str],
    numbers: dict[str, object],
    cited: str,
    stages: tuple[StageUse, ...] = (),
    tolerances: dict[str, Tolerance] | None = None,
) -> SensorSpec:
    per_axis: dict[str, dict[str, float]] = {}
    fields = dict(numbers)
    for field in ("noise_density_ug_rthz", "mech_cutoff_hz"):
        value = fields[field]
        if isinstance(value, AxisValues):
            for axis in ("x", "y", "z"):
                per_axis.setdefault(axis, {})[field] = getattr(value, axis)
            fields[field] = value.x
    if fields["digital_cutoff_hz"] is None:
        fields["digital_order"] = None
    elif fields["digital_order"] is not None:
        fields["digital_order"] = int(fields["digital_order"])  # type: ignore[call-overload]
    fields["adc_bits"] = int(fields["adc_bits"])  # type: ignore[call-overload]
    name = canonical_name(part.name, mode)
    try:
        return SensorSpec(
            name=name,
            description=f"{part.manufacturer} {part.description}".strip(),
            source=cited,
            plugin=part.plugin,
            distribution=part.distribution,
            per_axis=per_axis or None,
            stages=stages,
            tolerances=tolerances or {},
            **fields,  # type: ignore[arg-type]
        )
    except ValidationError as exc:
        raise ModeError(f"part {part.name!r} in mode {name}: {field_errors(exc)[0][1]}") from None
