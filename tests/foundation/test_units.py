"""One units module: standard gravity from its source, and no other module spells g or a table.

g_n is read from ``sdt_framework/units.toml``, which quotes the 3rd CGPM's
declaration; the test finds the value in those printed words (980.665 cm/s2).
Before this module, g and the unit tables were spelled in nine places (``TO_G``,
``UNITS_TO_G``, two ``G``, ``G0``, ``UNIT_RATIOS``, a pydantic ``Literal``, the
CLI's ``UNITS``, the readers' spellings); a second copy can drift from the
first, so the scan below fails on any module of the framework or the built-in
plugins that spells g_n (or 1/g_n) or a table of acceleration units.
"""

from __future__ import annotations

import ast
import re
import tomllib
from pathlib import Path

import pytest

import sdt_framework
from sdt_framework import units

PACKAGE = Path(sdt_framework.__file__).parent
REPO = PACKAGE.parent
#: where code lives that converts units: the framework and its built-in plugins
SCANNED = (PACKAGE, REPO / "plugins")
UNITS_MODULE = PACKAGE / "units.py"
#: g_n and its inverse, as digits: 9.80665 m/s^2, 980.665 cm/s^2, 0.10197... g per m/s^2
DIGITS = re.compile(r"9\.80665|980\.665|0\.1019716")
#: an acceleration unit's spelling other than plain g (a tuple holding "g" alone is no table)
NOT_G = set(units.SPELLINGS) - {"g"}


def test_standard_gravity_is_the_value_its_source_prints():
    data = tomllib.loads((PACKAGE / "units.toml").read_text(encoding="utf-8"))
    entry = data["standard_gravity"]
    assert "3rd" in entry["doc"] and "CGPM" in entry["doc"] and "p. 70" in entry["where"]
    printed = re.search(r"(\d+\.\d+) cm/s2", entry["printed"])
    assert printed is not None, entry["printed"]
    assert float(printed.group(1)) / 100 == units.G_N  # cm/s^2 -> m/s^2, exact


def test_the_table_converts_each_unit_to_g():
    one_g = {"g": 1.0, "mg": 1000.0, "m/s^2": float(units.G_N)}  # 1 g in each unit
    assert set(units.TO_G) == set(one_g) == set(units.UNITS)
    for unit, amount in one_g.items():
        assert amount * units.TO_G[unit] == pytest.approx(1.0, rel=1e-15)
    assert units.units_list() == "g, mg, m/s^2"
    assert units.units_list(" or ") == "g, mg or m/s^2"


@pytest.mark.parametrize(
    ("spelt", "name"),
    [("m/s²", "m/s^2"), ("M/S**2", "m/s^2"), (" m  s^-2 ", "m/s^2"), ("gn", "g"), ("mG", "mg"),
     ("V", None), ("", None), (None, None)],
)  # fmt: skip
def test_file_spellings_map_to_the_unit_names(spelt, name):
    assert units.acceleration_units(spelt) == name


def test_every_spelling_names_a_unit_of_the_table():
    assert set(units.SPELLINGS.values()) == set(units.UNITS)
    assert set(units.UNITS) <= set(units.SPELLINGS)


def _sources() -> list[Path]:
    return sorted(p for root in SCANNED for p in root.rglob("*.py") if p != UNITS_MODULE)


def _strings(node: ast.AST) -> set[str]:
    """The string constants a container literal holds (a dict's keys and values)."""
    if isinstance(node, ast.Dict):
        items = [*node.keys, *node.values]
    elif isinstance(node, ast.List | ast.Tuple | ast.Set):
        items = list(node.elts)
    else:
        return set()
    return {i.value for i in items if isinstance(i, ast.Constant) and isinstance(i.value, str)}


def spelled(path: Path) -> list[str]:
    """Where ``path`` spells g_n or a table of acceleration units."""
    text = path.read_text(encoding="utf-8")
    found = [f"{path}:{text.count(chr(10), 0, m.start()) + 1}: {m.group()}"
             for m in DIGITS.finditer(text)]  # fmt: skip
    for node in ast.walk(ast.parse(text)):
        named = _strings(node) & set(units.SPELLINGS)
        if len(named) >= 2 and named & NOT_G:  # ("g", "mg"), {"mg": 1e-3, "m/s^2": ...}
            found.append(f"{path}:{node.lineno}: a table of {sorted(named)}")
    return found


def test_no_other_module_spells_g_or_a_unit_table():
    found = [line for path in _sources() for line in spelled(path)]
    assert len(_sources()) > 100
    assert found == [], "import them from sdt_framework.units:\n" + "\n".join(found)


def test_the_scan_finds_what_it_forbids(tmp_path):
    """The scan's own check: each way the tables were spelled before is found."""
    module = tmp_path / "old.py"
    module.write_text(
        'TO_G = {"g": 1.0, "mg": 1e-3, "m/s^2": 1 / 9.80665}\n'
        'UNITS = ("g", "mg", "m/s^2", "lsb")\n'
        "G = 9.80665\n"
        'units: Literal["g", "mg", "m/s^2"] | None = None\n'
        'SPELT = {"m/s2": "m/s^2", "gn": "g"}\n'
        'AXES = ("g", "x")\n',
        encoding="utf-8",
    )
    lines = [line.split(":")[1] for line in spelled(module)]
    assert sorted(set(lines)) == ["1", "2", "3", "4", "5"]
