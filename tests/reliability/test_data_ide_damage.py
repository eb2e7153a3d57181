"""A damaged or cut IDE file is never read silently short (issue 29, B1 and the weak IDE rows).

Copies of the shipped ``SSX66115.IDE`` (658,680 bytes; channel 8 holds 65,184
samples to 13.043 s) are damaged in a temporary folder: 2,000 random bytes at
byte 300,000, or one byte flipped every 5,000 from byte 200,000. idelib stops
at the damage and returns what it read (about 5.9 s, or 10.9 s): sdt must
refuse such a file, naming where reading stopped. A file cut at byte 400,000
(an interrupted copy) is read up to the element it is cut in, with a note; its
samples are then the intact file's first ones.
"""

from __future__ import annotations

import random
from pathlib import Path

import numpy as np
import pytest
from sdt_plugins.readers.ide.parse import read_ide

DATA = Path(__file__).parents[1] / "data" / "endaq"
SIZE = 658_680  # bytes of SSX66115.IDE


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _damaged(folder: Path, how: str) -> Path:
    data = bytearray((DATA / "SSX66115.IDE").read_bytes())
    assert len(data) == SIZE
    if how == "random":
        draw = random.Random(29)
        data[300_000:302_000] = bytes(draw.randrange(256) for _ in range(2000))
    else:
        for i in range(200_000, len(data), 5000):
            data[i] ^= 0xFF
    path = folder / f"{how}.IDE"
    path.write_bytes(bytes(data))
    return path


def _stop_byte(err: str) -> int:
    return int(err.split("stopped reading at byte ")[1].split(" ")[0].replace(",", ""))


@pytest.mark.parametrize(("how", "first_damage"), [("random", 300_000), ("flip", 200_000)])
@pytest.mark.parametrize(
    "command",
    [["dataset", "inspect"], ["twin", "check", "--sensor", "adxl345"]],
    ids=["inspect", "check"],
)
def test_a_damaged_ide_file_is_refused_naming_where_reading_stopped(
    sdt, tmp_path, how, first_damage, command
):
    path = _damaged(tmp_path, how)
    run = sdt(*command[:2], str(path), *command[2:])
    assert run.returncode == 2, run.stdout
    assert run.stderr.startswith("error:") and run.stderr.count("\n") == 1, run.stderr
    assert "damaged" in run.stderr and f"of {SIZE:,}" in run.stderr
    assert "Warning" not in run.stderr and "Traceback" not in run.stderr
    # reading stopped after the first damaged byte and before the end of the file
    assert first_damage < _stop_byte(run.stderr) < SIZE


def test_bytes_missing_inside_a_block_or_no_ide_at_all_are_refused(sdt, tmp_path):
    """399 bytes cut out of a data block that starts at byte 398,341: idelib reads the
    block's declared size into the next element and stops there; and a text file."""
    data = (DATA / "SSX66115.IDE").read_bytes()
    (tmp_path / "gap.IDE").write_bytes(data[: 398_341 + 2000] + data[398_341 + 2399 :])
    err = sdt("dataset", "inspect", str(tmp_path / "gap.IDE")).stderr
    assert "damaged" in err and 398_341 + 2000 < _stop_byte(err) < SIZE - 399, err
    (tmp_path / "text.IDE").write_bytes(b"hello world\n" * 100)
    run = sdt("dataset", "inspect", str(tmp_path / "text.IDE"))
    assert run.returncode == 2 and "not a readable enDAQ IDE file" in run.stderr, run.stderr


def test_a_damaged_ide_file_in_a_manifest_is_skipped_with_the_reason(sdt, tmp_path):
    _damaged(tmp_path, "random")
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,variable,sampling_rate_hz,machine,condition,severity,recording_id,channel\n"
        "random.IDE,32:z,3134.27,shaker,rest,,r1,z\n",
        encoding="utf-8",
    )
    run = sdt("dataset", "inspect", str(manifest), "--validate")
    assert run.returncode == 0, run.stderr
    assert "random.IDE: damaged: idelib stopped reading at byte" in run.stdout
    assert run.stdout.count("\nskipped ") == 1
    assert "(manifest line 2)" in run.stdout and "0 recordings" in run.stdout


def test_a_cut_ide_file_is_read_up_to_the_cut_with_a_note(sdt, tmp_path):
    cut = tmp_path / "cut.IDE"
    cut.write_bytes((DATA / "SSX66115.IDE").read_bytes()[:400_000])
    run = sdt("dataset", "inspect", str(cut))
    assert run.returncode == 0, run.stderr
    assert "note: cut.IDE: truncated: the file ends at byte 400,000" in run.stderr
    # the samples read are exactly the intact file's first ones, and fewer
    intact = read_ide(DATA / "SSX66115.IDE", 8, ["x"])
    short = read_ide(cut, 8, ["x"])
    n = short.values.shape[1]
    assert 0 < n < intact.values.shape[1]
    # same samples; the 832M1's calibration has a temperature term (channel 36), whose
    # readings after the cut are missing: a common factor within 0.1 %
    ratio = short.values / intact.values[:, :n]
    assert np.ptp(ratio) < 1e-6 and abs(ratio.mean() - 1) < 1e-3
    assert short.start_s == intact.start_s
    assert "truncated" in (short.note or "")


@pytest.mark.parametrize("kind", ["folder", "fifo", "device"])
def test_an_ide_path_that_is_not_a_file_says_what_it_is(sdt, tmp_path, kind):
    path = tmp_path / "x.IDE"
    if kind == "folder":
        path.mkdir()
    elif kind == "fifo":
        import os

        os.mkfifo(path)
    else:
        path.symlink_to("/dev/zero")
    run = sdt("dataset", "inspect", str(path))
    assert run.returncode == 2 and "no such" not in run.stderr, run.stderr
    expected = {"folder": "is a folder", "fifo": "a named pipe", "device": "character device"}
    assert expected[kind] in run.stderr


def test_non_ascii_channel_names_give_one_note_not_a_raw_warning(sdt, tmp_path):
    data = bytearray((DATA / "SSX66115.IDE").read_bytes())
    at = data.index(b"Main Acceleration")
    data[at : at + 4] = "Mäi".encode("latin-1") + b"n"  # same length: the EBML sizes hold
    path = tmp_path / "latin.IDE"
    path.write_bytes(bytes(data))
    run = sdt("dataset", "inspect", str(path))
    assert run.returncode == 0, run.stderr
    assert "UnicodeWarning" not in run.stderr and "ebmlite" not in run.stderr
    assert run.stderr.count("note: some names in the file are not ASCII text") == 1
    assert "M\ufffdin Acceleration" in run.stdout


def test_a_channel_holding_nan_is_refused_naming_its_first_sample():
    """What idelib returns for damaged sample bytes it did not stop at (channel 59 of the
    randomly damaged file holds one NaN): the first bad sample and its time are named."""
    from sdt_plugins.readers.ide.parse import _require_finite

    from sdt_framework.errors import SDTError

    times = np.arange(100) / 3134.0
    values = np.zeros((3, 100))
    values[1, 7] = np.nan
    values[2, 40] = np.inf
    with pytest.raises(SDTError) as caught:
        _require_finite("f.IDE", 32, times, values)
    assert str(caught.value) == (
        f"f.IDE: channel 32, sample 7 (at {7 / 3134:.4f} s): 2 non-finite value(s); "
        f"the file is damaged there"
    )
