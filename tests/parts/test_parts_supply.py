"""Every catalogue supply figure equals the datasheet words cited beside it.

The values live in one place (the part files and the paper profiles); this
test reads the ``printed`` quote stored beside each one and checks the number
against it: a single figure must be one of the quote's numbers (in the quote's
unit), a table's figure must be on the printed row of its output data rate, in
the column of its mode.
"""

from __future__ import annotations

import pytest
from sdt_sensors_catalog import load_parts

from sdt_framework.parts import resolve
from sdt_framework.parts.supply import PartFigure
from sdt_framework.specs.supply import printed_numbers

#: how many of the field's units one printed unit is (fields are uA and ms)
UNIT = {"": 1.0, "uA": 1.0, "µA": 1.0, "mA": 1e3, "nA": 1e-3, "ms": 1.0, "s": 1e3}

PARTS = [p for p in load_parts() if p.supply is not None]


def _rows(printed: str) -> dict[float, list[str]]:
    rows = [row.split() for row in printed.split("|")]
    return {float(row[0]): row[1:] for row in rows}


def _check_table(figure: PartFigure) -> None:
    keys = figure.mode_keys()
    if "|" not in figure.printed:  # a sentence ("22 µA at 3200 Hz ODR"): its ODR and figure
        quoted = printed_numbers(figure.printed)
        for label, value in figure.table.items():
            assert float(label) in quoted and value in quoted, (label, figure.printed)
        return
    rows = _rows(figure.printed)
    for label, value in figure.table.items():
        options = label.split(",")
        odr = float(options[-1])
        assert odr in rows, f"no printed row for ODR {odr:g} ({label})"
        row = rows[odr]
        # one key: the row's last column; 'mode,odr': the column of the mode
        cell = row[-1] if len(keys) == 1 else row[figure.columns.index(options[0])]
        assert float(cell) * UNIT[figure.printed_unit] == value, (label, row)


@pytest.mark.parametrize("part", PARTS, ids=lambda p: p.name)
def test_part_supply_figures_equal_their_printed_datasheet_words(part):
    for field, figure in part.supply.figures().items():
        if figure.absent is not None:
            assert figure.absent.strip(), field
            continue
        assert figure.doc in part.documents and figure.where and figure.printed
        if figure.table is not None:
            _check_table(figure)
        else:
            quoted = [n * UNIT[figure.printed_unit] for n in printed_numbers(figure.printed)]
            assert figure.value in quoted, (part.name, field, figure.printed)


@pytest.mark.parametrize("name", ["adxl345", "adxl357", "wilcoxon-786b10"])
def test_paper_profiles_carry_figures_equal_to_their_quotes(registry, name):
    supply = registry.sensor(name).supply
    assert supply is not None
    for field, figure in supply.figures().items():
        if figure.value is None:
            assert figure.absent, field
            continue
        quoted = [n * UNIT[figure.printed_unit] for n in printed_numbers(figure.printed)]
        assert figure.value in quoted, (name, field, figure.printed)


def test_paper_profile_and_catalogue_part_agree(registry):
    parts = {p.name: p for p in load_parts()}
    for profile, part in (("adxl345", "adxl345-ds"), ("adxl357", "adxl357-ds")):
        mine = registry.sensor(profile).supply
        theirs = resolve(parts[part], {}).sensor.supply  # the part's default mode = the profile's
        assert mine.measure_ua.value == theirs.measure_ua.value
        assert mine.standby_ua.value == theirs.standby_ua.value


def test_a_mode_the_table_lacks_has_no_figure_not_a_neighbours():
    lis3dh = next(p for p in load_parts() if p.name == "lis3dh")
    supply = resolve(lis3dh, {"mode": "lp", "odr": "1600"}).sensor.supply
    assert supply.measure_ua.value is None and "lp,1600" in supply.measure_ua.absent
    assert resolve(lis3dh, {"mode": "hr", "odr": "400"}).sensor.supply.measure_ua.value == 73


def test_supply_does_not_change_a_sensors_hash(registry):
    adxl345 = registry.sensor("adxl345")
    assert adxl345.content_hash() == adxl345.model_copy(update={"supply": None}).content_hash()
