"""``keep_parsed``: whole-file parses kept by the memory they hold, the last one always."""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.signals.parsed import Kept, keep_parsed


def _counted(keep_bytes: int):
    """A parse of ``n`` float64 values (``n * 8`` bytes), counting its calls by key."""
    calls: list[tuple[str, int]] = []

    @keep_parsed(keep_bytes, lambda array: array.nbytes)
    def parse(name: str, n: int) -> np.ndarray:
        calls.append((name, n))
        if n < 0:
            raise ValueError(f"{name}: damaged")
        return np.zeros(n)

    return parse, calls


def test_files_within_the_bound_are_parsed_once_each_in_any_order():
    parse, calls = _counted(keep_bytes=8 * 300)
    names = [("a", 100), ("b", 100), ("c", 100)]  # 2400 bytes: all kept
    for _ in range(3):
        for key in names:
            assert parse(*key).size == key[1]
    assert calls == names


def test_the_least_recently_used_file_goes_first():
    parse, calls = _counted(keep_bytes=8 * 250)
    parse("a", 100), parse("b", 100), parse("a", 100)  # a used after b
    parse("c", 100)  # 300 values > 250: b, the least recently used, goes
    parse("a", 100), parse("c", 100), parse("b", 100)
    assert calls == [("a", 100), ("b", 100), ("c", 100), ("b", 100)]


def test_a_parse_over_the_bound_is_still_kept_until_the_next_file():
    parse, calls = _counted(keep_bytes=8 * 10)
    big = parse("big", 1000)
    assert parse("big", 1000) is big  # scan, probe and read of one large file: one parse
    parse("small", 5)
    parse("big", 1000)
    assert calls == [("big", 1000), ("small", 5), ("big", 1000)]


def test_a_failed_parse_is_not_kept():
    parse, calls = _counted(keep_bytes=1000)
    for _ in range(2):
        with pytest.raises(ValueError, match="damaged"):
            parse("bad", -1)
    assert calls == [("bad", -1), ("bad", -1)]


def test_a_size_known_beforehand_makes_room_before_the_value_is_made():
    """The kept values and the one being made never hold more than the bound together."""
    kept: Kept[np.ndarray] = Kept(8 * 250, lambda array: array.nbytes)
    held_while_making: list[int] = []

    def make(n: int):
        def run() -> np.ndarray:
            held_while_making.append(kept.held)
            return np.zeros(n)

        return run

    for key in ("a", "b", "c"):  # 100 values each: a goes before c is made
        kept.get(key, make(100), size=800)
    assert held_while_making == [0, 800, 800]
    assert len(kept) == 2 and kept.held == 1600
    big = kept.get("big", make(1000), size=8000)  # over the bound alone: made alone, kept
    assert held_while_making[-1] == 0 and len(kept) == 1
    assert kept.get("big", make(1000), size=8000) is big


def test_a_uff_campaign_scanned_then_read_parses_each_file_once(tmp_path, readers, monkeypatch):
    """As a manifest then a benchmark use them: every file scanned, then every file read
    (before, the last file alone was kept, so each was parsed once per pass)."""
    import pyuff

    from sdt_framework.signals.files import read_signal, scan_file

    from .daq_files import catman_uff

    parsed: list[str] = []

    class CountingUFF(pyuff.UFF):
        def __init__(self, filename: str, *args, **kwargs) -> None:
            parsed.append(filename.rsplit("/", 1)[-1])
            super().__init__(filename, *args, **kwargs)

    monkeypatch.setattr(pyuff, "UFF", CountingUFF)
    rng = np.random.default_rng(0)
    signals = {k: np.round(rng.normal(size=(2, 200)), 4) for k in range(4)}
    files = [tmp_path / f"f{k}.uff" for k in signals]
    for k, file in enumerate(files):
        file.write_text(catman_uff({"a0": signals[k][0], "a1": signals[k][1]}, 1000.0))
    for file in files:
        assert [s.variable for s in scan_file(file, readers)[1]] == ["1", "2"]
    for k, file in enumerate(files):
        np.testing.assert_allclose(read_signal(file, readers, "2")[0], signals[k][1], atol=1e-9)
    assert sorted(parsed) == [f.name for f in files]
