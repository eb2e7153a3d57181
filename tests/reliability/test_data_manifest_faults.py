"""Manifest reader under hostile input: no recording lost, none counted twice, one clear line.

Each case here failed on main before the reliability round: two machines
sharing a recording_id gave two recordings with one id (the benchmark's
``{recording_id: recording}`` map then kept only one), a duplicate row doubled
a recording's acquisitions, ``severity = 1.7`` became 1, and a 0-byte, ragged
or non-UTF-8 manifest gave a pandas traceback.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework.data import open_manifest
from sdt_framework.errors import SDTError

HEADER = "path,sampling_rate_hz,condition,severity,recording_id,channel,machine\n"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    """Two distinct signals: a ramp 0..99 and a constant 7."""
    np.save(tmp_path / "ramp.npy", np.arange(100, dtype=float))
    np.save(tmp_path / "seven.npy", np.full(100, 7.0))
    return tmp_path


def write(folder: Path, text: str, name: str = "manifest.csv") -> Path:
    path = folder / name
    path.write_text(text)
    return path


def test_two_machines_reusing_a_run_and_channel_are_two_recordings(folder: Path, readers) -> None:
    manifest = write(
        folder,
        HEADER
        + "ramp.npy,1000,healthy,,run-1,ch1,Motor-A\n"
        + "seven.npy,1000,healthy,,run-1,ch1,Motor-B\n",
    )
    ds = open_manifest(manifest, readers=readers)
    recs = {r.recording_id: r for r in ds.recordings()}
    assert len(recs) == 2  # ids are unique: nothing keyed by id can merge them
    assert set(recs) == {"Motor-A/run-1/ch1", "Motor-B/run-1/ch1"}
    np.testing.assert_array_equal(recs["Motor-A/run-1/ch1"].load(), [np.arange(100.0)])
    np.testing.assert_array_equal(recs["Motor-B/run-1/ch1"].load(), [np.full(100, 7.0)])
    assert set(ds.runs()) == {"Motor-A/run-1", "Motor-B/run-1"}


def test_exact_duplicate_row_is_refused_naming_both_lines(folder: Path, readers) -> None:
    row = "ramp.npy,1000,healthy,,run-1,ch1,rig\n"
    manifest = write(folder, HEADER + row + "seven.npy,1000,healthy,,run-2,ch1,rig\n" + row)
    with pytest.raises(SDTError) as info:
        open_manifest(manifest, readers=readers)
    message = str(info.value)
    assert "line 2 and line 4 are identical" in message and str(manifest) in message


def test_one_signal_file_on_two_rows_is_refused(folder: Path, readers) -> None:
    manifest = write(
        folder,
        HEADER
        + "ramp.npy,1000,healthy,,run-1,ch1,rig\n"
        + "./ramp.npy,1000,bearing,2,run-2,ch1,rig\n",
    )
    with pytest.raises(SDTError, match=r"line 2 and line 3 both read .*ramp\.npy"):
        open_manifest(manifest, readers=readers)


@pytest.mark.parametrize("value", ["1.7", "2.5", "inf", "-0.1"])
def test_non_integer_severity_is_refused_naming_line_and_value(
    folder: Path, value: str, readers
) -> None:
    manifest = write(
        folder,
        HEADER
        + "ramp.npy,1000,healthy,,run-1,ch1,rig\n"
        + f"seven.npy,1000,bearing,{value},run-2,ch1,rig\n",
    )
    with pytest.raises(SDTError) as info:
        open_manifest(manifest, readers=readers)
    assert f"line 3: field 'severity' = '{value}' is not an integer" in str(info.value)


def test_integer_valued_float_severity_is_accepted(folder: Path, readers) -> None:
    """Parquet stores a column with empty cells as float: 2.0 is the level 2."""
    path = folder / "m.parquet"
    pd.DataFrame(
        {
            "path": ["ramp.npy", "seven.npy"],
            "sampling_rate_hz": [1000.0, 1000.0],
            "condition": ["healthy", "bearing"],
            "severity": [None, 2.0],
            "recording_id": ["r1", "r2"],
            "channel": ["x", "x"],
        }
    ).to_parquet(path)
    severities = {r.run: r.severity for r in open_manifest(path, readers=readers).recordings()}
    assert severities == {"r1": None, "r2": 2}


@pytest.mark.parametrize(
    ("content", "expected"),
    [
        (b"", "is empty (0 bytes)"),
        (
            (
                HEADER + "ramp.npy,1000,healthy,,run-1,ch1,rig\nseven.npy,1000,h,,r,ch1,rig,x\n"
            ).encode(),
            "line 3: 8 fields, the header (line 1) has 7",
        ),
        (
            (HEADER + "ramp.npy,1000,healthy,,run-1,ch1\n").encode(),
            "line 2: 6 fields, the header (line 1) has 7",
        ),
        (
            HEADER.encode() + b"ramp.npy,1000,healthy,,run-1,ch1,rig\n"
            b"seven.npy,1000,d\xe9faut,1,run-2,ch1,rig\n",
            "line 3: not UTF-8 text (byte 0xe9)",
        ),
        (HEADER.encode(), "a header and no rows"),
    ],
    ids=["zero-bytes", "long-row", "short-row", "latin-1", "header-only"],
)
def test_broken_manifest_is_one_line_naming_file_and_line(
    sdt_main, folder: Path, monkeypatch, capsys, content: bytes, expected: str
) -> None:
    manifest = folder / "manifest.csv"
    manifest.write_bytes(content)
    code, _, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 2 and "Traceback" not in err
    assert err.count("\n") == 1 and expected in err and str(manifest) in err


def test_headerless_csv_signal_keeps_its_first_row(folder: Path, readers) -> None:
    """pyarrow took line 1 of a header-less CSV as column names: one sample per column lost."""
    values = np.random.default_rng(3).normal(size=(50, 2))
    np.savetxt(folder / "two.csv", values, delimiter=",", fmt="%.17g")
    manifest = write(folder, HEADER + "two.csv,1000,healthy,,run-1,ch1,rig\n")
    (rec,) = open_manifest(manifest, readers=readers).recordings()
    np.testing.assert_array_equal(rec.load(), values.T)


def test_time_column_of_a_manifest_csv_is_noted(
    sdt_main, folder: Path, monkeypatch, capsys, readers
) -> None:
    t = np.arange(200) / 1000
    np.savetxt(folder / "a.csv", np.c_[t, np.sin(t)], delimiter=",", fmt="%.9g")  # no header
    manifest = write(folder, HEADER + "a.csv,1000,healthy,,run-1,ch1,rig\n")
    ds = open_manifest(manifest, readers=readers)
    (rec,) = ds.recordings()
    np.testing.assert_allclose(rec.load(), [np.sin(t)], rtol=1e-8)
    (note,) = ds.notes
    assert "a.csv" in note and "column 1 read as time" in note
    code, out, _ = sdt_main("dataset", "inspect", str(manifest), "--json")
    assert code == 0 and json.loads(out)["notes"] == [note]
