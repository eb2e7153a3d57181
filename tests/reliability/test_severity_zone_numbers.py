"""A zone table's boundaries and band are TOML numbers, nothing else (issue 39, item 9).

On main pydantic's lax mode read ``b_c = true`` as 1.0 mm/s and
``a_b = "1.0"`` (a string) as 1.0: a typo in a plant's own limits graded
every window against a boundary nobody wrote, with exit 0. A boolean or a
string is now one line naming the file, the field and what was written, exit
2; integers stay numbers (``c_d = 5`` is 5.0 mm/s).
"""

from __future__ import annotations

import pytest

from sdt_framework.severity import load_zone_file

from ..severity.test_severity_tables import GOOD  # boundaries a_b 1.0, b_c 2.0, c_d 5.0

#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _table(a_b: object, b_c: object, band: str = "") -> str:
    """GOOD with these boundaries (and a band line), c_d an integer."""
    line = f"{band}boundaries = {{ a_b = {a_b}, b_c = {b_c}, c_d = 5 }}"
    return GOOD.replace("boundaries = { a_b = 1.0, b_c = 2.0, c_d = 5.0 }", line)


@pytest.mark.parametrize(
    ("a_b", "b_c", "band", "field", "words"),
    [
        ("1.0", "true", "", "table.0.boundaries.b_c", "got the boolean true"),
        ('"1.0"', "2.0", "", "table.0.boundaries.a_b", "got the string '1.0': drop the quotes"),
        (
            "1.0",
            "2.0",
            'band_hz = ["10", 1000]\n',
            "table.0.band_hz",
            "got the string '10': drop the quotes",
        ),
        ("1.0", "2.0", "band_hz = [10, false]\n", "table.0.band_hz", "got the boolean false"),
    ],
    ids=["boolean", "string", "band-string", "band-boolean"],
)
def test_a_boundary_that_is_not_a_number_is_one_line(sdt, tmp_path, a_b, b_c, band, field, words):
    path = tmp_path / "plant.toml"
    path.write_text(_table(a_b, b_c, band), encoding="utf-8")
    done = sdt("compare", str(tmp_path / "no-results"), "--zones", str(path))
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr == f"error: {path}: field {field!r}: must be a number, {words}\n"


def test_integers_are_numbers(tmp_path):
    path = tmp_path / "plant.toml"
    path.write_text(_table(1, 2, "band_hz = [10, 1000]\n"), encoding="utf-8")
    (table,) = load_zone_file(path)
    assert table.cuts.tolist() == [1.0, 2.0, 5.0] and table.band_hz == (10.0, 1000.0)
