"""Every catalogue part states its price: an indicative one with its source, or none found.

A part without a public price carries ``[no_price]`` (what was searched and
when), so "no public price" is a checked statement, never a forgotten field;
the schema refuses a part giving both, and an empty search list.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from sdt_framework.errors import SDTError
from sdt_framework.parts import load_part_text

pytestmark = pytest.mark.catalog
catalogue = pytest.importorskip("sdt_sensors_catalog", reason="install plugins/sensors-catalog")
PARTS = {p.name: p for p in catalogue.load_parts()}
ADXL355 = Path(catalogue.__file__).parent / "parts" / "adxl355.toml"


def test_every_part_has_a_price_or_says_none_was_found() -> None:
    for name, part in PARTS.items():
        assert (part.price is None) != (part.no_price is None), name
    unpriced = sorted(n for n, p in PARTS.items() if p.no_price is not None)
    assert unpriced == [
        "adxl1002",
        "adxl313",
        "adxl355",
        "bmi270",
        "iim42352",
        "ism330dhcx",
        "kx134",
        "lis2dw12",
        "lis3dh",
        "mpu6050",
    ]
    for name in unpriced:
        searched = PARTS[name].no_price
        assert searched.date and searched.searched, name
        assert all("query" in s for s in searched.searched), name  # says what was asked


def _with(extra: str) -> str:
    return ADXL355.read_text() + "\n" + extra


def test_a_part_with_both_a_price_and_no_price_is_refused() -> None:
    price = '[price]\namount = 1.0\ncurrency = "EUR"\nquantity = "1"\nsource = "x"\ndate = "d"\n'
    with pytest.raises(SDTError, match=r"\[price\] or \[no_price\]"):
        load_part_text(_with(price), "adxl355.toml")


def test_no_price_needs_what_was_searched() -> None:
    text = ADXL355.read_text()
    start = text.index("[no_price]")
    end = text.index("[values.", start)
    empty = text[:start] + '[no_price]\nsearched = []\ndate = "2026-11-26"\n\n' + text[end:]
    with pytest.raises(SDTError, match=r"no_price\.searched"):
        load_part_text(empty, "adxl355.toml")
