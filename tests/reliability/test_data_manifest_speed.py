"""A manifest's speed_rpm under hostile input: one line naming the line and the value, exit 2.

A speed of 0 would divide every order by zero, a negative one or NaN place
every order line nowhere, text or inf are no speed at all; each is refused
where it is read (``sdt``'s entry point in this process: exit status and
stderr as printed). Two rows of one recording that disagree on the speed are one
recording at two speeds: it is left out with both lines named, never merged.
A benchmark config's ``speeds`` that are not speeds are refused the same way.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest

from sdt_framework.bench.config import load_config
from sdt_framework.data import open_manifest
from sdt_framework.errors import SDTError, SpecFileError

HEADER = "path,sampling_rate_hz,condition,severity,recording_id,channel,speed_rpm\n"


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    np.save(tmp_path / "a.npy", np.arange(100, dtype=float))
    np.save(tmp_path / "b.npy", np.ones(100))
    return tmp_path


@pytest.mark.parametrize("value", ["0", "-1480", "nan", "NaN", "inf", "fast", "1,480", "١٤٨٠"])
def test_a_speed_that_is_no_speed_is_one_line_and_exit_2(folder: Path, sdt, value) -> None:
    cell = f'"{value}"' if "," in value else value
    manifest = folder / "m.csv"
    manifest.write_text(
        HEADER + "a.npy,1000,healthy,,r1,ch1,1480\n" + f"b.npy,1000,healthy,,r2,ch1,{cell}\n",
        encoding="utf-8",
    )
    result = sdt("dataset", "inspect", str(manifest))
    assert result.returncode == 2, result.stderr
    (line,) = result.stderr.splitlines()
    assert line == (
        f"error: manifest {manifest} line 3: field 'speed_rpm' = {value!r} is not a shaft "
        f"speed; give the speed in rpm as a positive number (1480), or leave the cell empty "
        f"where it is not known"
    )


def test_a_parquet_nan_is_refused_and_a_null_is_not_known(folder: Path, readers) -> None:
    rows = {
        "path": ["a.npy", "b.npy"],
        "sampling_rate_hz": [1000.0, 1000.0],
        "condition": ["healthy", "healthy"],
        "severity": [None, None],
        "recording_id": ["r1", "r2"],
        "channel": ["ch1", "ch1"],
    }
    good = folder / "good.parquet"
    pq.write_table(pa.table({**rows, "speed_rpm": [1480.0, None]}), good)
    a, b = open_manifest(good, readers=readers).recordings()
    assert (a.speed_rpm, b.speed_rpm) == (1480.0, None)
    bad = folder / "bad.parquet"
    pq.write_table(pa.table({**rows, "speed_rpm": [1480.0, float("nan")]}), bad)
    with pytest.raises(SDTError, match=r"row 2: field 'speed_rpm' = 'nan' is not a shaft speed"):
        open_manifest(bad, readers=readers)


def test_rows_of_one_recording_at_two_speeds_are_left_out_naming_both(folder, readers) -> None:
    manifest = folder / "m.csv"
    manifest.write_text(
        HEADER + "a.npy,1000,healthy,,r1,ch1,1480\n" + "b.npy,1000,healthy,,r1,ch1,740\n",
        encoding="utf-8",
    )
    dataset = open_manifest(manifest, readers=readers)
    assert dataset.recordings() == []
    (skipped,) = dataset.skipped
    expected = f"rows disagree on speed_rpm (manifest {manifest} line 2, line 3)"
    assert skipped.reason.endswith(expected)


@pytest.mark.parametrize(
    ("speeds", "says"),
    [
        ("[0]", "0 is not a speed; give a positive number (% of rated)"),
        ("[-50]", "-50 is not a speed; give a positive number (% of rated)"),
        ("[true]", "true is not a speed; give a number (50) or a label ('50')"),
        ("['']", "'' is not a speed; give a number (50) or a label ('50')"),
        ("[]", "must name at least one entry"),
        ("[50, 50]", "lists a name twice"),
        ("nan", "should be a valid list"),
    ],
)
def test_a_config_speed_that_is_no_speed_is_refused(tmp_path, speeds, says) -> None:
    config = tmp_path / "c.toml"
    config.write_text(f"[benchmark]\nspeeds = {speeds}\n", encoding="utf-8")
    with pytest.raises(SpecFileError) as error:
        load_config(config, {})
    assert "speeds" in str(error.value) and says in str(error.value)
    assert "\n" not in str(error.value)


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (["--nominal-rpm", "0"], "error: --nominal-rpm 0: give the shaft speed in rpm, above 0"),
        (
            ["--nominal-rpm", "nan"],
            "error: --nominal-rpm nan: give the shaft speed in rpm, above 0",
        ),
        (["--nominal-rpm", "-5"], "error: --nominal-rpm -5: give the shaft speed in rpm, above 0"),
        (
            ["--speeds", "50"],
            "error: --speeds: {m} has no speed folders to choose from (its dataset takes no "
            "speeds option); drop --speeds: its recordings show their speed",
        ),
        (
            ["--speeds", "50,,75"],
            "error: --speeds '50,,75': an empty name; give 'all' or e.g. 50,75,100",
        ),
    ],
)
def test_inspect_options_that_are_no_speed_are_one_line(folder: Path, sdt, args, says) -> None:
    manifest = folder / "m.csv"
    manifest.write_text(HEADER + "a.npy,1000,healthy,,r1,ch1,\n", encoding="utf-8")
    result = sdt("dataset", "inspect", str(manifest), *args)
    assert result.returncode == 2, result.stderr
    assert result.stderr.splitlines() == [says.format(m=manifest)]
