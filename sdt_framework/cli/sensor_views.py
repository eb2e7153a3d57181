"""What ``sdt sensors list`` and ``show`` print about parts: summaries, rows, provenance.

Pure functions from specs to JSON-ready dicts and table rows, tested without a
terminal. Which profiles and parts pass the list's filters is
:func:`sdt_framework.parts.search`; here only the option text of a price.
"""

from __future__ import annotations

import re
from typing import Any

from ..errors import SDTError
from ..parts import PartSpec, PriceLimit, all_modes, resolve
from ..specs import SensorSpec

__all__ = ["parse_price", "part_json", "part_row", "sensor_json"]


def parse_price(text: str) -> PriceLimit:
    """``"10"`` -> 10 in the prices' one currency; ``"10EUR"`` or ``"10 eur"`` -> 10 EUR."""
    match = re.fullmatch(r"\s*([0-9]+(?:\.[0-9]*)?)\s*([A-Za-z]{3})?\s*", text)
    if match is None:
        raise SDTError(f"--max-price {text!r}: give an amount, optionally with a currency: 10EUR")
    return PriceLimit(float(match[1]), match[2].upper() if match[2] else None)


def sensor_json(spec: SensorSpec) -> dict[str, Any]:
    """A sensor profile as JSON: every field, tolerances, provenance, derived step and hash."""
    return {
        **spec.content_dict(),
        "tolerances": {k: t.model_dump(exclude_none=True) for k, t in spec.tolerances.items()},
        "kind": "sensor",
        "plugin": spec.plugin,
        "distribution": spec.distribution,
        "quantisation_step_g": spec.quantisation_step_g,
        "content_hash": spec.content_hash(),
    }


def _fmt(value: float) -> str:
    return f"{value:g}"


def _tolerance_text(tolerance: Any) -> str:
    spread = f"{tolerance.spread_pct:g} %" if tolerance.spread is None else f"{tolerance.spread:g}"
    what = "SD" if tolerance.distribution == "normal" else "+-"
    return f"{tolerance.distribution} {what} {spread}"


def sampling_text(model: str) -> str:
    """A sampling model as `sensors show` prints it: the paper's named as such."""
    return f"{model} (the paper's model)" if model == "sample-then-filter" else model


def profile_cell(spec: SensorSpec, field: str, data: dict[str, Any]) -> Any:
    """The value of ``field`` as `sensors show` prints it: stages and tolerances readable."""
    if field == "sampling":
        return sampling_text(spec.sampling)
    if field == "stages":
        uses = []
        for use in spec.stages:
            params = ", ".join(f"{k}={v}" for k, v in use.params.items())
            extra = [f"{a}: {v}" for a, v in (use.per_axis or {}).items()]
            extra += [f"{k} {_tolerance_text(t)}" for k, t in use.tolerances.items()]
            uses.append(f"{use.name}({params})" + (f" [{'; '.join(extra)}]" if extra else ""))
        return "; ".join(uses) or None
    if field == "tolerances":
        items = spec.tolerances.items()
        return "; ".join(f"{k}: {_tolerance_text(t)}" for k, t in items) or None
    return data.get(field)


def _span(values: list[float], unit: str = "") -> str:
    low, high = min(values), max(values)
    return f"{_fmt(low)}{unit}" if low == high else f"{_fmt(low)}–{_fmt(high)}{unit}"


def _summary(part: PartSpec) -> dict[str, Any]:
    sensors = [resolve(part, mode).sensor for mode in all_modes(part)]
    return {
        "rates_hz": sorted({float(s.sampling_rate_hz) for s in sensors}),
        "full_scale_g": sorted({float(s.full_scale_g or 0) for s in sensors}),
        "adc_bits": sorted({int(s.adc_bits or 0) for s in sensors}),
        "noise_x_ug_rthz": sorted({s.noise_density_ug_rthz for s in sensors}),
        "sensors": sensors,
    }


def part_json(part: PartSpec) -> dict[str, Any]:
    """A part as JSON: modes, ranges over its modes, the default mode's sensor, price, sources."""
    summary = _summary(part)
    default = resolve(part)
    return {
        "name": part.name,
        "kind": "part",
        "manufacturer": part.manufacturer,
        "description": part.description,
        "interface": part.interface,
        "modes": {
            key: {"options": list(mode.options), "default": mode.default, "why": mode.default_why}
            for key, mode in sorted(part.modes.items())
        },
        "default_sensor": default.sensor.name,
        **{k: v for k, v in summary.items() if k != "sensors"},
        "noise_density_ug_rthz": default.sensor.noise_density_ug_rthz,
        "per_axis": default.sensor.per_axis,
        "price": part.price.model_dump() if part.price else None,
        "no_price": part.no_price.model_dump() if part.no_price else None,
        "documents": {k: d.model_dump() for k, d in part.documents.items()},
        "notes": list(part.notes),
        "plugin": part.plugin,
        "distribution": part.distribution,
        "content_hash": part.content_hash(),
    }


def _modes_text(part: PartSpec) -> str:
    lines = []
    for key, mode in sorted(part.modes.items()):
        labels = list(mode.options)
        if mode.field and len(labels) > 4:
            values = [mode.label_value(label) for label in labels]
            text = f"{_span(values, mode.unit)} ({len(labels)})"
        else:
            text = ", ".join(labels)  # spaces let a narrow table wrap the list
        lines.append(f"{key}: {text}; default {mode.default}")
    return "\n".join(lines) or "-"


def part_row(part: PartSpec) -> list[str]:
    """One row of the parts table."""
    summary = _summary(part)
    sensor = resolve(part).sensor
    axes = [sensor.for_axis(a).noise_density_ug_rthz for a in "xyz"]
    noise = _fmt(axes[0]) if len(set(axes)) == 1 else "/".join(map(_fmt, axes)) + " (x/y/z)"
    price = f"{part.price.amount:g} {part.price.currency}" if part.price else "-"
    return [
        part.name,
        _modes_text(part),
        _span(summary["rates_hz"]),
        _span(summary["full_scale_g"]),
        _span([float(b) for b in summary["adc_bits"]]),
        f"{noise}\n({_span(summary['noise_x_ug_rthz'])} over modes)"
        if len(summary["noise_x_ug_rthz"]) > 1
        else noise,
        price,
        part.distribution or "",
    ]


def provenance_rows(resolved: Any) -> tuple[list[list[str]], list[str]]:
    """Rows per chain value (value, document id, where, basis, set by) and the stand-in notes."""
    rows, notes = [], []
    for src in resolved.sources:
        value = src.value
        if isinstance(value, dict):
            text = "/".join(_fmt(value[a]) for a in "xyz") + " (x/y/z)"
        elif isinstance(value, str):
            text = sampling_text(value)
        else:
            text = "none" if value is None else _fmt(value)
        if src.odr_fraction is not None:
            text += f" (ODR × {src.odr_fraction:g})"
        if src.absent:
            text += " *"
            notes.append(
                f"* {src.field}: not in the documents ({src.absent}); stand-in "
                f"{'from ' + src.doc if src.doc else 'none'}: {src.why}"
            )
        elif src.note:
            notes.append(f"{src.field}: {src.note}")
        rows.append([src.field, text, src.doc or src.source, src.where, src.basis, src.set_by])
    return rows, notes


def _axes_text(values: dict[str, float], unit: str = "") -> str:
    unit = f" {unit}" if unit else ""
    if len(set(values.values())) == 1:
        return f"{_fmt(values['x'])}{unit}"
    return "/".join(_fmt(values[a]) for a in "xyz") + f"{unit} (x/y/z)"


def _term_note(term: Any) -> str:
    parts = [f"{term.term}: printed '{term.printed}'"]
    if term.range_c is not None:
        parts.append(f"stated for {term.range_c[0]:g} to {term.range_c[1]:g} °C")
    if term.stand_in:
        parts.append(f"stand-in: the part's documents lack it ({term.absent}); {term.why}")
    if term.note:
        parts.append(term.note)
    return "; ".join(parts)


def error_rows(resolved: Any) -> tuple[str, list[list[str]], list[str]]:
    """A part's error terms in a mode: a title saying on or off, one row per term, notes."""
    if not resolved.terms:
        return "", [], []
    if any(t.enabled for t in resolved.terms):
        keys = ", ".join(f"{k}={v}" for k, v in sorted(resolved.error_mode.items()))
        title = (
            f"Error terms: on ({keys}). Each unit of sdt benchmark --units N draws its own "
            f"values; the nominal unit has none; the tempcos act only away from 25 °C"
        )
    else:
        given = {t.term for t in resolved.terms if t.figure is not None}
        keys = [f"{resolved.part.name}[errors=datasheet] (tempcos, nonlinearity)"]
        if "cross_axis" in given:
            keys.append("cross_axis=datasheet (a triaxial node)")
        if given & {"offset_tempco", "sensitivity_tempco"}:
            keys.append("temp=85c (the tempcos act only away from 25 °C)")
        title = (
            f"Error terms: off. Enable with {', '.join(keys)}; units are drawn by "
            f"sdt benchmark --units N"
        )
    rows, notes = [], []
    for term in resolved.terms:
        if term.figure is None:
            figure, per_unit = "absent *", "-"
            why = (
                f"; stand-in: {term.why}" if term.stand_in else f"; {term.why}" if term.why else ""
            )
            notes.append(f"* {term.term}: {term.absent}{why}")
        else:
            figure = "±" + _axes_text(term.figure, term.unit)
            size = "SD " if term.distribution == "normal" else "±"
            per_unit = f"{term.distribution} {size}{_axes_text(term.spread or {})}"
            factor = (term.spread or {})["x"] / term.figure["x"]
            if abs(factor - 1) > 1e-9:
                per_unit += f" ({factor:g} × figure)"
            notes.append(_term_note(term))
        on = "on" if term.enabled else "off"
        rows.append([term.term, figure, f"{per_unit} → {term.stage}", on, term.doc, term.where])
    return title, rows, notes
