"""docs/sensors.md's catalogue table lists every part with its default noise, rates and bits."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from sdt_framework.cli.sensor_views import part_json
from sdt_framework.parts import resolve

pytestmark = pytest.mark.catalog
catalogue = pytest.importorskip("sdt_sensors_catalog", reason="install plugins/sensors-catalog")
DOC = Path(__file__).resolve().parents[2] / "docs" / "sensors.md"


def span(values) -> str:
    low, high = min(values), max(values)
    return f"{low:g}" if low == high else f"{low:g}–{high:g}"


def test_the_documented_table_matches_the_catalogue():
    rows = {
        m[1]: [c.strip() for c in m[2].split("|")]
        for m in re.finditer(r"^\| `([a-z0-9-]+)` \|(.*)\|$", DOC.read_text(), re.M)
    }
    parts = {p.name: p for p in catalogue.load_parts()}
    assert set(rows) == set(parts)
    for name, part in parts.items():
        _, noise, rate, bits, full_scale, price, _ = rows[name]
        data = part_json(part)
        sensor = resolve(part).sensor
        axes = [sensor.for_axis(a).noise_density_ug_rthz for a in "xyz"]
        shown = f"{axes[0]:g}" if len(set(axes)) == 1 else "/".join(f"{a:g}" for a in axes)
        assert noise.split(" (")[0] == shown, name
        assert (rate, bits, full_scale) == (
            span(data["rates_hz"]),
            span(data["adc_bits"]),
            span(data["full_scale_g"]),
        ), name
        assert price == (
            f"{part.price.amount:g} {part.price.currency}" if part.price else "no public price"
        )
