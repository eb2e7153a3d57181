"""``sdt twin check --json`` prints byte for byte what it printed before its results were typed.

The check's results were nested dicts until issue 42 made them frozen
dataclasses; a script reading the JSON must not see the change. The expected
files are the outputs of main at 4c97f2b on three real recordings
(``tests/data/twin_check/README.md``); each is compared as bytes, so a key's
order, a float's digits or a ``null`` that moved fails here.
"""

from __future__ import annotations

from pathlib import Path

import pytest

DATA = Path(__file__).parents[1] / "data"
CASES = {
    "SSX66115_adxl345.json": ["SSX66115.IDE", "--sensor", "adxl345"],
    "DAQ12006_000005_adxl357_scale1.626.json": [
        "DAQ12006_000005.IDE", "--sensor", "adxl357", "--reference-scale", "1.626"],
    "Cloud_Test_000000_adxl357.json": ["Cloud_Test_000000.IDE", "--sensor", "adxl357"],
}  # fmt: skip


@pytest.mark.parametrize("expected", sorted(CASES))
def test_the_json_is_byte_identical(sdt_main, expected):
    file, *options = CASES[expected]
    code, out, err = sdt_main("twin", "check", str(DATA / "endaq" / file), *options, "--json")
    assert (code, err) == (0, "")
    assert out.encode() == (DATA / "twin_check" / expected).read_bytes()
