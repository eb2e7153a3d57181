"""LVM and UFF files are sized before they are parsed (issue 39, weak item).

lvm_read and pyuff hold a whole file as Python objects: on main a 105 MB LVM took 41 s and
1.8 GB in ``inspect`` and ``manifest``, a 5 GB UFF 5 GB. A file over the format's bound (LVM
50 MB, UFF 1 GB), or one whose parse (measured bytes of memory per byte of file) cannot fit
in the memory available, is now refused before any parsing, naming the size and what to do.
The over-bound files here are sparse: a real head, then a hole, so no test writes 1 GB.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from .labview import lvm, segment

DATA = Path(__file__).parents[1] / "data" / "readers"
LVM_ADVICE = (
    "save the recording from LabVIEW as TDMS (Write To Measurement File, format TDMS), or "
    "split it into LVM files of at most 50 MB"
)
UFF_ADVICE = "export fewer or shorter functions per file (one file per channel or run)"


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def _sparse(file: Path, head: bytes, size: int) -> Path:
    with open(file, "wb") as handle:
        handle.write(head)
        handle.truncate(size)
    return file


def _never_parsed(monkeypatch) -> None:
    """Parsing the file would fail the test: the refusal must come first."""
    import lvm_read
    import pyuff

    def parse(*args, **kwargs):
        raise AssertionError("the file was parsed")

    monkeypatch.setattr(lvm_read, "read", parse)
    monkeypatch.setattr(pyuff, "UFF", parse)


def _lvm_text(n: int = 2048) -> bytes:
    rows = np.round(np.random.default_rng(0).normal(scale=0.3, size=(n, 1)), 6)
    return lvm([segment(["acc"], rows, 1 / 25_600)]).encode()


def test_an_lvm_over_50_mb_is_refused_before_parsing(sdt_main, tmp_path, monkeypatch):
    file = _sparse(tmp_path / "long.lvm", _lvm_text(), 60_000_000)
    _never_parsed(monkeypatch)
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: a 60.0 MB LVM file; sdt parses LVM text files up to 50.0 MB (their "
        f"reader holds the whole file as Python objects); {LVM_ADVICE}"
    )


def test_a_uff_over_1_gb_is_refused_before_parsing(sdt_main, tmp_path, monkeypatch):
    head = (DATA / "Sample_UFF58_ascii.uff").read_bytes()
    file = _sparse(tmp_path / "long.uff", head, 1_100_000_000)
    _never_parsed(monkeypatch)
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: a 1.1 GB UFF file; sdt parses UFF text files up to 1.0 GB (their "
        f"reader holds the whole file as Python objects); {UFF_ADVICE}"
    )


@pytest.mark.parametrize(
    ("name", "per_byte", "advice"),
    [("rec.lvm", 22, LVM_ADVICE), ("Sample_UFF58_ascii.uff", 5, UFF_ADVICE)],
)
def test_a_parse_that_cannot_fit_in_memory_is_refused(
    sdt_main, tmp_path, monkeypatch, name, per_byte, advice
):
    """The memory a parse needs is the file's size times the reader's measured bytes per
    byte (lvm_read 22, pyuff 5): with 100 kB free, neither file may be parsed."""
    file = tmp_path / name
    if name.endswith(".lvm"):
        file.write_bytes(_lvm_text())
    else:
        file.write_bytes((DATA / name).read_bytes())
    size = file.stat().st_size
    assert size * per_byte > 100_000
    monkeypatch.setattr("sdt_framework.signals.file_sizes.available_memory", lambda: 100_000)
    _never_parsed(monkeypatch)
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    fmt = "LVM" if name.endswith(".lvm") else "UFF"
    from sdt_framework.signals.sizes import human_bytes

    assert _one_error_line(err) == (
        f"error: {file}: parsing this {human_bytes(size)} {fmt} file needs about "
        f"{human_bytes(size * per_byte)} of memory, more than the 100.0 kB available; {advice}"
    )


def test_the_manifest_builder_lists_an_oversized_lvm_as_not_used(sdt_main, tmp_path):
    for run in ("r1", "r2"):
        (tmp_path / "tree" / "healthy" / run).mkdir(parents=True)
    (tmp_path / "tree/healthy/r1/ch1.lvm").write_bytes(_lvm_text())
    _sparse(tmp_path / "tree/healthy/r2/ch1.lvm", _lvm_text(), 60_000_000)
    out = tmp_path / "m.csv"
    code, stdout, err = sdt_main(
        "dataset", "manifest", str(tmp_path / "tree"),
        "--pattern", "{condition}/{run}/{channel}.lvm", "--out", str(out),
    )  # fmt: skip
    assert code == 0, err
    assert "1 rows from 1 files" in stdout and "1 not used" in stdout
    assert (
        "not used: healthy/r2/ch1.lvm: a 60.0 MB LVM file; sdt parses LVM text files up to 50.0 MB"
    ) in err
