"""A table never cuts a number or drops a column, however narrow the output.

On main, ``sdt budget --interval 0.0001s | cat`` (80 columns) printed DR0's
transmit energy as ``4484`` where the value is 448408269.62 J/day, and
``--axes 1000000 | cat`` lost whole columns.
"""

from __future__ import annotations

import json

import pytest

COLUMNS = ("DR", "SF/kHz", "max B", "fits", "uplinks", "ToA ms", "duty ok", "TX mJ", "TX J/day")


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _budget(sdt, *args: str):
    narrow = {"COLUMNS": "80"}  # what a pipe or a file gets
    table = sdt("budget", *args, env=narrow)
    data = sdt("budget", *args, "--json", env=narrow)
    assert table.returncode == 0 and data.returncode == 0, table.stderr + data.stderr
    return table.stdout, json.loads(data.stdout)


@pytest.mark.parametrize("args", [["--interval", "0.0001s"], ["--axes", "1000000"], []])
def test_every_digit_and_every_column_is_printed(sdt, args):
    text, data = _budget(sdt, *args)
    flat = " ".join(text.split())  # a folded cell may wrap; its digits stay in order
    for column in COLUMNS:
        assert column in text
    for row in data["rows"]:
        # transmit energy per day from its parts: I x V x time on air x reports per day
        radio = data["radio"]
        per_day = (
            radio["tx_current_a"]
            * radio["supply_v"]
            * row["time_on_air_s"]
            * data["reports_per_day"]
        )
        assert row["energy_per_day_j"] == pytest.approx(per_day, rel=1e-9)
        assert f"{per_day:.2f}" in flat or f"{per_day:.1f}" in flat, row["data_rate"]


def test_the_issue_case_prints_the_whole_energy(sdt):
    text, _ = _budget(sdt, "--interval", "0.0001s")
    assert "448408269.62" in text  # 0.029 A x 3.3 V x 5.423104 s x 8.64e8 reports/day
