"""OS and library errors around `sdt benchmark`: one line (exit 2) or one warning, never a crash."""

from __future__ import annotations

import errno
import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework import SDTError
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.bench.scenarios import Run, load_allocation
from sdt_framework.data.cache import default_cache_dir
from sdt_framework.io import atomic_write_text

SMALL_CLI = ["benchmark", "--quick", "--machines", "Motor-2", "--sensors", "adxl345"]
SMALL_CLI += ["--classifiers", "lr", "--channels", "ch1", "--jobs", "1", "--no-report"]

#: the commands here are refused before any work: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def one_error_line(result) -> str:
    assert result.returncode == 2, result.stderr
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    return lines[0]


def test_read_only_cache_folder(sdt, read_only_dir, tmp_path):
    line = one_error_line(
        sdt(*SMALL_CLI, "--cache-dir", str(read_only_dir), "--out", str(tmp_path / "o"))
    )
    assert f"cannot write the feature cache {read_only_dir}" in line
    assert "choose another with --cache-dir or SDT_CACHE_DIR" in line
    assert not (tmp_path / "o").exists()  # checked before the results folder is claimed


def test_read_only_out_folder(sdt, read_only_dir):
    line = one_error_line(sdt(*SMALL_CLI, "--out", str(read_only_dir / "results")))
    assert f"{read_only_dir / 'results'}" in line and "--out" in line


@pytest.mark.parametrize("home", [None, "", "/nonexistent/home"])
def test_missing_home_without_a_cache_setting(monkeypatch, home):
    environ = {} if home is None else {"HOME": home}
    monkeypatch.setattr("pwd.getpwuid", lambda uid: (_ for _ in ()).throw(KeyError(uid)))
    with pytest.raises(SDTError, match=r"set SDT_CACHE_DIR \(or --cache-dir\) to a writable"):
        default_cache_dir(environ)
    assert default_cache_dir({**environ, "SDT_CACHE_DIR": "/data/c"}) == Path("/data/c")


def test_missing_home_is_one_line_from_the_command(sdt, tmp_path):
    line = one_error_line(
        sdt(*SMALL_CLI, "--out", str(tmp_path / "o"), env={"HOME": "", "SDT_CACHE_DIR": ""})
    )
    assert "cannot find your home folder (HOME is not set)" in line


def full_disk(monkeypatch, fails: Callable[[Path], bool]):
    """Make writes of the files ``fails`` picks stop half-way, as on a full disk (ENOSPC)."""
    original = Path.write_bytes

    def write_bytes(self: Path, data: bytes) -> int:
        if fails(self):
            original(self, data[: len(data) // 2])
            raise OSError(errno.ENOSPC, "No space left on device")
        return original(self, data)

    monkeypatch.setattr(Path, "write_bytes", write_bytes)


def test_disk_full_leaves_the_old_file_and_no_half_written_one(monkeypatch, tmp_path):
    target = tmp_path / "summary.json"
    target.write_text("old, complete")
    full_disk(monkeypatch, lambda path: "summary.json" in path.name)
    with pytest.raises(SDTError) as caught:
        atomic_write_text(target, "new " * 1000)
    assert str(caught.value) == (
        f"cannot write {target}: No space left on device; "
        f"free some disk space or choose a folder on another disk"
    )
    assert isinstance(caught.value, OSError)  # a cache may still choose to carry on
    assert target.read_text() == "old, complete"
    assert [p.name for p in tmp_path.iterdir()] == ["summary.json"]


def test_disk_full_while_storing_a_run(monkeypatch, small_config, registry, tmp_path):
    full_disk(monkeypatch, lambda path: path.parent.name == "runs")  # runs/<key>.json
    out = tmp_path / "out"
    with pytest.raises(SDTError, match=r"cannot write .*runs/.*\.json: No space left on device"):
        run_benchmark(plan_benchmark(small_config(), registry), out)
    assert list((out / "runs").iterdir()) == []


def test_corrupt_feature_cache_entries_are_named_discarded_and_recomputed(
    small_config, registry, tmp_path
):
    config = small_config()
    clean = tidy(run_benchmark(plan_benchmark(config, registry), tmp_path / "a").runs)[0]
    entries = sorted((tmp_path / "cache" / "features").rglob("*.npz"))
    entries[0].write_bytes(entries[0].read_bytes()[:100])  # truncated: zip header, no index
    entries[1].write_bytes(b"not an archive")  # numpy reads it as a (refused) pickle
    np.savez(entries[2], values=np.zeros((3, 2)))  # an archive of the wrong arrays
    with pytest.warns(RuntimeWarning) as warned:
        again = run_benchmark(plan_benchmark(config, registry), tmp_path / "b")
    notes = [str(w.message) for w in warned if str(w.message).startswith("corrupt")]
    kinds = ["BadZipFile", "ValueError", "KeyError"]
    assert sorted(notes) == sorted(
        f"corrupt feature-cache entry {entry} ({kind}) discarded; recomputing it"
        for entry, kind in zip(entries[:3], kinds, strict=True)
    )
    assert again.features_computed == 3
    pd.testing.assert_frame_equal(
        tidy(again.runs)[0].drop(columns="fit_seconds"), clean.drop(columns="fit_seconds")
    )
    assert run_benchmark(plan_benchmark(config, registry), tmp_path / "c").features_computed == 0


def test_truncated_or_foreign_run_files_are_named_ignored_and_recomputed(
    small_config, registry, tmp_path
):
    out = tmp_path / "out"
    config = small_config()
    clean = tidy(run_benchmark(plan_benchmark(config, registry), out).runs)[0]
    files = sorted((out / "runs").glob("*.json"))
    files[0].write_text(files[0].read_text()[:40])  # truncated by a crash of another tool
    files[1].write_text("[1, 2, 3]")  # foreign JSON
    record = json.loads(files[2].read_text())
    files[2].write_text(json.dumps({**record, "macro_f1": "0.9"}))  # wrong type
    (out / "runs" / "notes.json").write_text(json.dumps(record))  # key does not match name
    with pytest.warns(RuntimeWarning) as warned:
        again = run_benchmark(plan_benchmark(config, registry), out)
    notes = [str(w.message) for w in warned if str(w.message).startswith("ignoring")]
    assert notes == [
        f"ignoring {files[0]}: not a complete JSON document; its run will be computed again",
        f"ignoring {files[1]}: a JSON list, not a run record; its run will be computed again",
        f"ignoring {files[2]}: field 'macro_f1' has the wrong type (str); "
        f"its run will be computed again",
        f"ignoring {out / 'runs' / 'notes.json'}: holds run {record['key']!r}, not the one its "
        f"name says; its run will be computed again",
    ]
    assert (again.runs_computed, again.runs_resumed) == (3, 9)
    pd.testing.assert_frame_equal(
        tidy(again.runs)[0].drop(columns="fit_seconds"), clean.drop(columns="fit_seconds")
    )
    assert json.loads(files[0].read_text())["key"] == files[0].stem  # replaced by the new run


@pytest.mark.parametrize(
    ("address", "reason"),
    [
        ("tcp://::nonsense", "invalid address '::nonsense'; maybe: ipv6 needs brackets like [::1]"),
        ("foo", "missing port number in address 'foo'"),
    ],
)
def test_malformed_dask_scheduler_address(sdt_in_process, tmp_path, address, reason):
    out = tmp_path / "o"  # refused before any work or connection: in this process
    line = one_error_line(
        sdt_in_process(*SMALL_CLI, "--backend", "dask", "--scheduler", address, "--out", str(out))
    )
    assert line == (
        f"error: --scheduler {address!r} is not a Dask scheduler address ({reason}); "
        f"e.g. tcp://192.168.1.10:8786"
    )
    assert not out.exists()


@pytest.mark.parametrize(
    ("address", "reason"),
    [
        ("tcp://10.0.0.1:99999", "a host and a port between 1 and 65535 are needed"),
        ("tcp://:8786", "a host and a port between 1 and 65535 are needed"),
        ("http://h:1", "unknown scheme 'http'; known: inproc, tcp, tls, ucx, ws, wss"),
    ],
)
def test_other_malformed_scheduler_addresses(address, reason):
    from sdt_framework.bench.execute import check_scheduler_address

    with pytest.raises(SDTError) as caught:
        check_scheduler_address(address)
    assert f"({reason})" in str(caught.value)


RUNS = [Run("Motor-2", "healthy 1", "healthy", None)]
SHAPE = "expected [[allocation]] tables, each with machine, scenario, run and side as strings"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            'allocation = [{machine = "Motor-2"}, 3]\n',
            "allocation entry 1: 'scenario' is missing; expected a string",
        ),
        ("allocation = [1, 2]\n", f"allocation entry 1 is of type int; {SHAPE}"),
        ('allocation = "x"\n', f"'allocation' is of type str; {SHAPE}"),
        ('[allocation]\nmachine = "Motor-2"\n', f"'allocation' is of type dict; {SHAPE}"),
        ("[benchmark]\nrepeats = 1\n", f"'allocation' is missing; {SHAPE}"),
        (
            '[[allocation]]\nmachine = ["Motor-2"]\nscenario = "forward"\nrun = "healthy 1"\n'
            'side = "train"\n',
            "allocation entry 1: 'machine' is of type list; expected a string",
        ),
    ],
)
def test_allocation_toml_of_the_wrong_shape(tmp_path, text, message):
    path = tmp_path / "allocation.toml"
    path.write_text(text)
    with pytest.raises(SDTError) as caught:
        load_allocation(path, RUNS)
    assert str(caught.value) == f"{path}: {message}"


def test_allocation_path_that_is_a_folder(tmp_path):
    with pytest.raises(SDTError, match=r"cannot read the allocation table \(Is a directory\)"):
        load_allocation(tmp_path, RUNS)
