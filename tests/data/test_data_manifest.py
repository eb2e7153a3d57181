"""Manifest reader: CSV/NPY/MAT signals, units, grouping, missing files, bad fields."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import scipy.io

from sdt_framework.data import open_manifest
from sdt_framework.errors import SDTError

HEADER = "path,sampling_rate_hz,condition,severity,recording_id,channel,machine,units,variable\n"


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    sig = tmp_path / "signals"
    sig.mkdir()
    np.save(sig / "a.npy", np.arange(100, dtype=float))
    np.save(sig / "b.npy", np.ones((2, 100)))
    scipy.io.savemat(sig / "c.mat", {"acc": np.full((100, 3), 2.0), "other": np.zeros(3)})
    pd.DataFrame({"time": np.arange(100) / 1000, "x": np.full(100, 9.80665)}).to_csv(
        sig / "d.csv", index=False
    )
    return tmp_path


def write(folder: Path, rows: list[str], header: str = HEADER) -> Path:
    path = folder / "manifest.csv"
    path.write_text(header + "\n".join(rows) + "\n")
    return path


def test_formats_units_and_grouping(folder: Path, readers) -> None:
    manifest = write(
        folder,
        [
            "signals/a.npy,1000,healthy,,run-1,x,rig,mg,",
            "signals/b.npy,1000,healthy,,run-1,x,rig,mg,",
            "signals/c.mat,1000,bearing,2,run-2,y,rig,g,acc",
            f"{folder / 'signals' / 'd.csv'},1000,bearing,2,run-2,z,rig,m/s^2,x",
        ],
    )
    ds = open_manifest(manifest, readers=readers)
    recs = {r.recording_id: r for r in ds.recordings()}
    assert set(recs) == {"rig/run-1/x", "rig/run-2/y", "rig/run-2/z"}  # machine/run/channel
    x = recs["rig/run-1/x"]
    assert (x.run, x.severity) == ("run-1", None)
    assert (x.n_acquisitions, x.samples_per_acquisition) == (3, 100)
    np.testing.assert_allclose(x.load()[0], np.arange(100) * 1e-3)  # mg -> g
    np.testing.assert_allclose(x.load()[1:], 1e-3)
    y = recs["rig/run-2/y"]
    assert (y.severity, y.n_acquisitions) == (2, 3)  # MATLAB columns are acquisitions
    np.testing.assert_allclose(y.load(), 2.0)
    np.testing.assert_allclose(recs["rig/run-2/z"].load(), 1.0)  # 9.80665 m/s^2 = 1 g
    assert ds.skipped == [] and set(ds.runs()) == {"rig/run-1", "rig/run-2"}


def test_missing_file_is_skipped_with_row(folder: Path, readers) -> None:
    manifest = write(
        folder,
        [
            "signals/a.npy,1000,healthy,,run-1,x,rig,g,",
            "signals/gone.npy,1000,healthy,,run-2,x,rig,g,",
        ],
    )
    ds = open_manifest(manifest, readers=readers)
    assert [r.run for r in ds.recordings()] == ["run-1"]
    (skip,) = ds.skipped
    assert "gone.npy" in skip.path and "line 3" in skip.reason and "not found" in skip.reason
    assert ds.describe()["summary"]["skipped"] == 1


def test_non_finite_value_reported_and_others_load(folder: Path, readers) -> None:
    values = np.zeros(100)
    values[42] = np.nan
    np.save(folder / "signals" / "nan.npy", values)
    manifest = write(
        folder,
        [
            "signals/nan.npy,1000,healthy,,run-1,x,rig,g,",
            "signals/a.npy,1000,healthy,,run-2,x,rig,g,",
        ],
    )
    ds = open_manifest(manifest, readers=readers, validate=True)
    assert [r.run for r in ds.recordings()] == ["run-2"]
    (skip,) = ds.skipped
    assert "nan.npy" in skip.reason and "sample 42" in skip.reason


@pytest.mark.parametrize(
    ("header", "row", "field"),
    [
        (HEADER.replace("units", "unit"), "signals/a.npy,1000,h,,r,x,rig,g,", "'unit'"),
        (HEADER, "signals/a.npy,1000,h,,r,x,rig,volts,", "'units'"),
        (HEADER, "signals/a.npy,fast,h,,r,x,rig,g,", "'sampling_rate_hz'"),
        (HEADER, "signals/a.npy,1000,h,high,r,x,rig,g,", "'severity'"),
        (HEADER.replace("channel,", ""), "signals/a.npy,1000,h,,r,rig,g,", "'channel'"),
    ],
)
def test_bad_fields_are_user_errors(
    folder: Path, header: str, row: str, field: str, readers
) -> None:
    with pytest.raises(SDTError, match=field):
        open_manifest(write(folder, [row], header), readers=readers)


def test_parquet_manifest(folder: Path, readers) -> None:
    path = folder / "m.parquet"
    pd.DataFrame(
        {
            "path": ["signals/a.npy"],
            "sampling_rate_hz": [1000.0],
            "condition": ["healthy"],
            "severity": [None],
            "recording_id": ["r1"],
            "channel": ["x"],
        }
    ).to_parquet(path)
    (rec,) = open_manifest(path, readers=readers).recordings()
    assert (rec.machine, rec.units, rec.severity, rec.sampling_rate_hz) == (
        "machine",
        "g",
        None,
        1000.0,
    )
