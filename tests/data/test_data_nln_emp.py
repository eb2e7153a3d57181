"""NLN-EMP reader: discovery, parsing, grouping, subsets, cache, malformed files."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
from sdt_plugins.datasets.nln_emp import csv_file as nln_emp_csv
from sdt_plugins.datasets.nln_emp import open_nln_emp, parse_condition

from sdt_framework.errors import SDTError

STEP = 5e-05


def write_csv(root: Path, machine: str, speed: str, run: str, ch: str, data: np.ndarray) -> Path:
    """One file in exactly the published format: header time,0,1,..., time step 5e-05."""
    folder = root / "Vibration" / machine / speed / run
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"Vibration_{machine}_{speed}_time-{run}-{ch}.csv"
    n_acq, n = data.shape
    lines = ["time," + ",".join(str(i) for i in range(n_acq))]
    for row in range(n):
        lines.append(f"{row * STEP:.5f}," + ",".join(f"{v:.6g}" for v in data[:, row]))
    path.write_text("\n".join(lines) + "\n")
    return path


def signal(seed: int, n_acq: int = 7, n: int = 300) -> np.ndarray:
    return np.round(np.random.default_rng(seed).normal(0, 1, (n_acq, n)), 4)


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    runs = [
        ("Motor-4", "70", "align angular 3"),
        ("Motor-4", "70", "healthy 2"),
        ("Motor-4", "70", "coupling 2D"),
        ("Motor-4", "70", "healthy noise"),
        ("Motor-4", "50", "healthy 1"),
        ("Motor-2", "100", "bearing bpfo 1"),
        ("Motor-2", "100", "align angular 1"),
    ]
    for i, (machine, speed, run) in enumerate(runs):
        for ch in ("ch1", "ch3"):
            write_csv(tmp_path, machine, speed, run, ch, signal(i))
    return tmp_path


def test_parse_condition() -> None:
    assert parse_condition("align angular 3") == ("align angular", 3)
    assert parse_condition("healthy 2") == ("healthy", None)
    with pytest.raises(ValueError):
        parse_condition("coupling 2D")


def test_discovery_defaults_to_paper_subsets(tree: Path, tmp_path: Path) -> None:
    ds = open_nln_emp(tree, cache_dir=tmp_path / "cache")
    runs = {(r.machine, r.speed, r.run) for r in ds.recordings()}
    # Motor-4 at 50 % and Motor-2 'align angular' are not in the paper subsets
    assert runs == {
        ("Motor-4", "70", "align angular 3"),
        ("Motor-4", "70", "healthy 2"),
        ("Motor-2", "100", "bearing bpfo 1"),
    }
    rec = next(r for r in ds.recordings() if r.run == "healthy 2" and r.channel == "ch3")
    assert (rec.condition, rec.severity) == ("healthy", None)
    assert rec.recording_id == "Motor-4/70/healthy 2/ch3"
    assert (rec.n_acquisitions, rec.samples_per_acquisition) == (7, 300)
    assert rec.sampling_rate_hz == 20000.0
    assert rec.measurement == (0, 0, 0, 0, 0, 1, 1)  # columns 0-4 form one 60 s measurement
    angular = [r for r in ds.recordings() if r.run == "align angular 3"]
    assert {(r.condition, r.severity) for r in angular} == {("align angular", 3)}
    assert len(ds.runs()["Motor-4/align angular 3"]) == 2  # both channels in one run
    reasons = {Path(s.path).name: s.reason for s in ds.skipped}
    assert "unknown condition" in reasons["coupling 2D"]
    assert "unknown condition" in reasons["healthy noise"]
    assert ds.describe()["summary"]["skipped"] == len(ds.skipped) >= 2


def test_values_and_subset_options(tree: Path, tmp_path: Path) -> None:
    ds = open_nln_emp(
        tree,
        motors=["Motor-4"],
        speeds="50",
        channels="ch3",
        max_acquisitions=2,
        cache_dir=tmp_path / "cache",
    )
    (rec,) = ds.recordings()
    assert (rec.run, rec.channel, rec.n_acquisitions) == ("healthy 1", "ch3", 2)
    data = rec.load()
    assert data.dtype == np.float64 and data.shape == (2, 300)
    np.testing.assert_allclose(data, signal(4)[:2], rtol=1e-6)
    named = open_nln_emp(tree, conditions=["coupling 2D"], cache=False)
    assert {r.run for r in named.recordings()} == {"coupling 2D"}
    assert {r.severity for r in named.recordings()} == {None}


def test_cache_hit_and_invalidation(tree: Path, tmp_path: Path, monkeypatch) -> None:
    calls = []
    real = nln_emp_csv.parse_nln_csv

    def counting(path, *args, **kwargs):
        calls.append(Path(path).name)
        return real(path, *args, **kwargs)

    monkeypatch.setattr("sdt_plugins.datasets.nln_emp.reader.parse_nln_csv", counting)
    cache = tmp_path / "cache"
    rec = open_nln_emp(tree, channels="ch1", cache_dir=cache).recordings()[0]
    first = rec.load()
    assert len(calls) == 1 and list((cache / "arrays").glob("*.npz"))
    again = open_nln_emp(tree, channels="ch1", cache_dir=cache).recordings()[0].load()
    assert len(calls) == 1
    np.testing.assert_array_equal(first, again)
    changed = signal(99)
    write_csv(tree, rec.machine, rec.speed, rec.run, rec.channel, changed)
    stat = Path(rec.source).stat()
    os.utime(rec.source, ns=(stat.st_atime_ns, stat.st_mtime_ns + 10**9))
    fresh = open_nln_emp(tree, channels="ch1", cache_dir=cache).recordings()[0].load()
    assert len(calls) == 2
    np.testing.assert_allclose(fresh, changed, rtol=1e-6)


@pytest.mark.parametrize(
    ("mutate", "expected"),
    [
        (lambda lines: lines.__setitem__(40, lines[40].rsplit(",", 1)[0]), "line 41: expected 8"),
        (lambda lines: lines.__setitem__(12, lines[12] + "x"), "line 13, column '6'"),
        (lambda lines: lines.__setitem__(0, "t,0,1,2,3,4,5,6"), "line 1: header"),
        (
            lambda lines: lines.__setitem__(
                77, lines[77].replace(",", ",inf,", 1).rsplit(",", 1)[0]
            ),
            "line 78, column '0': non-finite",
        ),
        (
            lambda lines: lines.__setitem__(30, lines[30].replace(",", ",,", 1).rsplit(",", 1)[0]),
            "line 31, column '0': empty value",
        ),
    ],
)
def test_malformed_file_is_skipped_and_others_load(tree: Path, mutate, expected: str) -> None:
    bad = next((tree / "Vibration" / "Motor-4" / "70" / "healthy 2").glob("*-ch1.csv"))
    lines = bad.read_text().splitlines()
    mutate(lines)
    bad.write_text("\n".join(lines) + "\n")
    ds = open_nln_emp(tree, cache=False, validate=True)
    problems = [s for s in ds.skipped if s.path == str(bad)]
    assert len(problems) == 1 and expected in problems[0].reason, ds.skipped
    assert str(bad) in problems[0].reason
    assert len(ds.recordings()) == 5  # the six selected files minus the bad one
    assert all(r.load().shape == (7, 300) for r in ds.recordings())
    assert ds.describe()["summary"]["skipped"] == 3  # two unknown directories + the bad file


def test_missing_root_is_user_error(tmp_path: Path) -> None:
    with pytest.raises(SDTError, match="no 'Vibration' folder"):
        open_nln_emp(tmp_path)
