"""A part's text is validated once per process: building the registry again (a notebook,
a sweep, the suite) does not parse the catalogue again; another text is another part."""

from __future__ import annotations

import pytest

from sdt_framework.errors import SpecFileError
from sdt_framework.parts import files
from sdt_framework.registry import build_registry

pytestmark = pytest.mark.catalog
part_files = pytest.importorskip(
    "sdt_sensors_catalog", reason="install plugins/sensors-catalog (make does)"
).part_files


@pytest.fixture
def validated(monkeypatch) -> list[str]:
    """The names every part validation is called with, from an empty memo."""
    seen: list[str] = []
    validate = files._validate

    def counting(data, where):
        seen.append(str(where))
        return validate(data, where)

    monkeypatch.setattr(files, "_validate", counting)
    files.load_part_text.cache_clear()
    yield seen
    files.load_part_text.cache_clear()  # nothing validated by the counter stays behind


def test_a_second_registry_validates_no_part_again(validated) -> None:
    first = build_registry()
    catalogue = len(part_files())
    assert len(validated) == catalogue >= 10
    second = build_registry()
    assert len(validated) == catalogue
    assert [p.name for p in second.parts()] == [p.name for p in first.parts()]
    assert second.part("adxl355") == first.part("adxl355")


def test_another_text_is_another_part_and_a_bad_one_fails_every_time(validated) -> None:
    text = part_files()[0].read_text(encoding="utf-8")
    where = "mine/part.toml"
    part = files.load_part_text(text, where)
    assert files.load_part_text(text, where) is part
    edited = "# edited\n" + text
    assert edited != text
    assert files.load_part_text(edited, where) == part  # same content, validated anew
    assert validated == [where, where]
    for _ in range(2):
        with pytest.raises(SpecFileError, match=r"mine/bad\.toml"):
            files.load_part_text(text + "\nunknown_key = 1\n", "mine/bad.toml")
    assert validated == [where, where, "mine/bad.toml", "mine/bad.toml"]
