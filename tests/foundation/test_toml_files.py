"""The shared TOML reader: what it accepts and the one line each fault becomes."""

from __future__ import annotations

import pytest

from sdt_framework.errors import SpecFileError
from sdt_framework.toml_files import MAX_DEPTH, parse_toml, read_toml


def test_a_utf8_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "c.toml"
    path.write_bytes(b"\xef\xbb\xbfa = 1\n[t]\nb = 'x'\n")
    assert read_toml(path) == {"a": 1, "t": {"b": "x"}}


def test_nesting_beyond_the_limit_names_the_top_level_key():
    shallow = "x = " + "[" * MAX_DEPTH + "]" * MAX_DEPTH
    assert parse_toml(shallow, "f.toml")["x"] is not None
    deep = "a = 1\ny = " + "[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1)
    with pytest.raises(SpecFileError) as info:
        parse_toml(deep, "f.toml")
    assert info.value.field == "y" and "more than 32 levels deep" in str(info.value)


def test_a_missing_file_gets_the_callers_advice(tmp_path):
    with pytest.raises(SpecFileError, match=r"gone\.toml: sweep file not found; try X$"):
        read_toml(tmp_path / "gone.toml", missing="sweep file not found; try X")


def test_broken_toml_names_the_line():
    with pytest.raises(
        SpecFileError, match=r"^f\.toml: not valid TOML: Invalid value \(at line 2, column 4\)$"
    ):
        parse_toml("a = 1\nb =\n", "f.toml")
