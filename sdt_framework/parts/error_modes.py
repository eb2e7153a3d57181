"""Enabling a part's error terms: the mode keys ``errors``, ``cross_axis`` and ``temp``.

The terms are off by default, so a part's default chain stays the paper's and
its names and hashes stay as they were. ``errors=datasheet`` adds the offset
and sensitivity temperature coefficients and the nonlinearity;
``cross_axis=datasheet`` adds the cross-axis sensitivity (a node stage: it
needs the three axes of a triaxial node); ``temp=85c`` sets the temperature
the part runs at (default 25c, the datasheets' reference, where the
temperature coefficients do nothing). A key at its default is left out of the
canonical name: ``adxl355[errors=datasheet,odr=4000,range=2g,temp=85c]``.

A datasheet's ± figure says where a unit's value lies, not its sign, so each
term becomes a stage with nominal value 0 and a per-unit tolerance, drawn by
``sdt benchmark --units N``: a normal with SD = the typical figure, truncated
at 3 SD; or uniform over ± the maximum where the document gives only a
maximum, or where 3 typical SDs would pass its maximum. Without ``--units``
the nominal unit has no error at all and equals the default mode's output.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import asdict, dataclass
from typing import Any

from ..errors import SDTError
from ..specs.stage_use import StageUse, Tolerance
from .error_terms import REFERENCE_C, TERMS, ErrorTerm
from .values import Document

__all__ = [
    "ERROR_KEYS",
    "ErrorTermsError",
    "TermSource",
    "error_stages",
    "shown_keys",
    "split_error_keys",
    "term_sources",
]

OFF, ON = "off", "datasheet"
#: the keys that enable error terms, with their defaults (left out of canonical names)
ERROR_KEYS = {"errors": OFF, "cross_axis": OFF, "temp": f"{REFERENCE_C:g}c"}
#: which terms each key enables
ENABLES = {
    "errors": ("offset_tempco", "sensitivity_tempco", "nonlinearity"),
    "cross_axis": ("cross_axis",),
}
_TEMP = re.compile(r"^(-?[0-9]+(?:\.[0-9]+)?)c$")


class ErrorTermsError(SDTError):
    """An error-term key a part cannot honour: names the part, the key and what to do."""


@dataclass(frozen=True)
class TermSource:
    """One error term of a part in a mode: the figure, the per-unit draw, the provenance."""

    term: str
    stage: str  # "offset.tempco_mg_per_c"
    unit: str  # the parameter's unit
    figure: dict[str, float] | None  # per axis, in ``unit``; None where absent
    distribution: str  # "normal" (SD = figure) or "uniform" (± figure); "" where absent
    spread: dict[str, float] | None  # the stage parameter's per-unit SD or half-width, per axis
    enabled: bool
    printed: str = ""
    source: str = ""  # document title and revision
    doc: str = ""
    where: str = ""
    basis: str = ""
    range_c: tuple[float, float] | None = None
    note: str = ""
    absent: str = ""  # what the documents lack (in this mode)
    why: str = ""  # why the stand-in (or why none)
    stand_in: bool = False  # the figure comes from another document

    def as_dict(self) -> dict[str, object]:
        """JSON-ready view."""
        return asdict(self)


def _temperature(part: str, text: str) -> float:
    match = _TEMP.match(text)
    if match is None:
        raise ErrorTermsError(
            f"part {part!r}: temp={text} is not a temperature; give deg C with a 'c', "
            f"e.g. temp=85c or temp=-40c"
        )
    return float(match[1])


def split_error_keys(part: Any, given: Mapping[str, str]) -> tuple[dict[str, str], dict[str, str]]:
    """``given`` without the error-term keys, and those keys checked, defaults filled in."""
    chain = {k: v for k, v in given.items() if k not in ERROR_KEYS}
    choice = {**ERROR_KEYS, **{k: v for k, v in given.items() if k in ERROR_KEYS}}
    for key in ("errors", "cross_axis"):
        if choice[key] not in (OFF, ON):
            raise ErrorTermsError(
                f"part {part.name!r}: {key}={choice[key]} is not an option; "
                f"{key} is one of {OFF}, {ON}"
            )
    choice["temp"] = f"{_temperature(part.name, choice['temp']):g}c"
    return chain, choice


def shown_keys(choice: Mapping[str, str]) -> dict[str, str]:
    """The error-term keys that belong in the canonical name: those not at their default."""
    return {k: v for k, v in choice.items() if v != ERROR_KEYS[k]}


def _distribution(term: ErrorTerm) -> str:
    return "normal" if term.basis == "typical" else "uniform"


def _source(documents: Mapping[str, Document], doc: str | None) -> str:
    if not doc:
        return ""
    d = documents[doc]
    return f"{d.title}, {d.revision}" + (" (secondary)" if d.secondary else "")


def term_sources(part: Any, mode: Mapping[str, str], choice: Mapping[str, str]) -> tuple:
    """Every term of ``part`` in ``mode``: figure, per-unit spread, provenance, on or off."""
    enabled = {t for key, terms in ENABLES.items() if choice[key] == ON for t in terms}
    rows = []
    for name, kind in TERMS.items():
        term = part.errors.get(name)
        if term is None:
            continue
        cited, axes = term.cited, term.figure(mode)
        figure = None if axes is None else axes.model_dump()
        reasons = [term.absent] if term.absent and cited is not term else []
        if cited is not None and cited.by is not None and axes is None:
            reasons.append(f"{cited.absent} (here {cited.by}={mode[cited.by]})")
        rows.append(
            TermSource(
                term=name,
                stage=f"{kind.stage}.{kind.param}",
                unit=kind.unit,
                figure=figure,
                distribution=_distribution(cited) if figure and cited else "",
                spread={a: kind.factor * v for a, v in figure.items()} if figure else None,
                enabled=name in enabled and figure is not None,
                printed=cited.printed if cited else "",
                source=_source(part.documents, cited.doc) if cited else "",
                doc=(cited.doc or "") if cited else "",
                where=cited.where if cited else "",
                basis=(cited.basis or "") if cited else "",
                range_c=cited.range_c if cited else None,
                note="; ".join(
                    dict.fromkeys(n for n in (term.note, cited.note if cited else "") if n)
                ),
                absent="; ".join(r for r in reasons if r),
                why=term.why,
                stand_in=cited is not None and cited is not term,
            )
        )
    _check(part, choice, rows)
    return tuple(rows)


def _check(part: Any, choice: Mapping[str, str], rows: list[TermSource]) -> None:
    """One clear line when a key asks for what the part's documents do not give."""
    by_term = {row.term: row for row in rows}
    for key, terms in ENABLES.items():
        if choice[key] != ON or any(by_term.get(t) and by_term[t].figure for t in terms):
            continue
        why = f"sdt sensors show {part.name} says why" if part.errors else "it lists no [errors]"
        raise ErrorTermsError(
            f"part {part.name!r}: {key}={ON}, but its documents give no "
            f"{' or '.join(TERMS[t].title for t in terms)} in this mode ({why})"
        )
    celsius = _temperature(part.name, choice["temp"])
    if celsius == REFERENCE_C:
        return
    tempcos = [row for row in rows if row.enabled and TERMS[row.term].temperature]
    if not tempcos:
        raise ErrorTermsError(
            f"part {part.name!r}: temp={choice['temp']} acts through the temperature "
            f"coefficients, and none is on; add errors={ON} (or leave temp out)"
        )
    for row in tempcos:
        if row.range_c is not None and not row.range_c[0] <= celsius <= row.range_c[1]:
            low, high = row.range_c
            raise ErrorTermsError(
                f"part {part.name!r}: temp={choice['temp']} is outside {low:g} to {high:g} °C, "
                f"the range its documents state for {row.term}; choose a temperature inside it"
            )


def error_stages(
    rows: tuple, choice: Mapping[str, str]
) -> tuple[tuple[StageUse, ...], dict[str, Tolerance]]:
    """The stages (nominal 0) and per-unit tolerances of the enabled terms.

    Tolerances are keyed ``"stage.parameter"`` (not by position), so unit k
    draws the same value for a term whichever other terms, range or
    temperature are selected: the same physical unit in every mode.
    """
    celsius = _temperature("", choice["temp"])
    temperature = {"kind": "constant", "celsius": celsius, "reference_c": REFERENCE_C}
    stages: list[StageUse] = []
    tolerances: dict[str, Tolerance] = {}
    for row in rows:
        if not row.enabled:
            continue
        kind = TERMS[row.term]
        params: dict[str, Any] = {kind.param: 0.0}
        if kind.temperature:
            params["temperature"] = temperature
        stages.append(StageUse(name=kind.stage, params=params))
        spread = row.spread or {}
        tolerances[row.stage] = Tolerance(
            distribution=row.distribution,
            spread=spread["x"],
            per_axis={"y": spread["y"], "z": spread["z"]},
        )
    return tuple(stages), tolerances
