"""`sdt sensors list` is an aligned table at 80-140 columns, folding between words.

On main the profile and part tables did not fit 80 (nor, for the parts, 140)
columns and fell back to one long `column: value` line per row (up to 300
characters). Now a distribution shared by every row is named once in the title,
mode options wrap after their commas, and each column is at least as wide as
its longest word, so no name or number is split.
"""

from __future__ import annotations

import json
import re

import pytest


@pytest.fixture
def listing(sdt_in_process):
    """``sdt sensors list ARGS`` on a terminal of ``columns`` columns: what it printed."""

    def run(columns: int, *args: str) -> str:
        result = sdt_in_process("sensors", "list", *args, env={"COLUMNS": str(columns)})
        assert result.returncode == 0, result.stderr
        return result.stdout

    return run


@pytest.mark.parametrize("columns", [80, 100, 140])
def test_aligned_tables_within_the_width_and_no_word_split(listing, columns):
    text = listing(columns)
    lines = text.splitlines()
    # the table uses the width it is given (80: 80, 100: 98, 140: 138) and never more
    assert columns - 5 <= max(len(line.rstrip()) for line in lines) <= columns
    assert not [line for line in lines if line.startswith(("name: ", "part: "))]  # no fallback
    assert sum(line.startswith("┏") for line in lines) == 2  # two boxed tables
    words = {w for line in lines for cell in line.split("│") for w in cell.split()}
    data = json.loads(listing(columns, "--json"))
    for entry in data:
        assert entry["name"] in words, entry["name"]  # a name is never folded
        rate = entry.get("sampling_rate_hz")
        if isinstance(rate, (int, float)):
            assert f"{rate:g}" in words
    # every row's cells sit under their headers: all box lines have the same separators
    boxes = [line for line in lines if line[:1] in "┏┃┡│└"]
    first_table = boxes[: next(i for i, b in enumerate(boxes) if b.startswith("└")) + 1]
    positions = {tuple(m.start() for m in re.finditer("[┃│┳╇┴┏┓┩┡└┘]", b)) for b in first_table}
    assert len(positions) == 1
