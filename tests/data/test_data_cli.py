"""``sdt dataset``: synth writes the NLN-EMP layout that inspect reads back."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from sdt_plugins.datasets.nln_emp import open_nln_emp
from sdt_plugins.datasets.synthetic_pump import open_synthetic

CLASSES = {
    "Motor-4": {
        "healthy": 3,
        "unbalance motor": 6,
        "unbalance pump": 3,
        "align angular": 5,
        "align parallel": 4,
        "align combination": 4,
        "coupling": 3,
        "cavitation suction": 3,  # levels 1, 3, 4: the real archive has no level 2
        "cavitation discharge": 5,
    },
    "Motor-2": {
        "healthy": 3,
        "impeller": 3,
        "bearing bpfo": 3,
        "bearing bpfi": 3,
        "bearing pump": 3,
    },
}


@pytest.fixture
def sdt(sdt_in_process):
    """``sdt(*args, env_cache=...)``: the command in this process (``dataset`` starts no worker)."""
    return lambda *args, env_cache: sdt_in_process(*args, env={"SDT_CACHE_DIR": str(env_cache)})


def test_synth_then_inspect_round_trip(sdt, tmp_path: Path) -> None:
    out = tmp_path / "syn"
    done = sdt(
        "dataset",
        "synth",
        "--out",
        str(out),
        "--duration",
        "0.5",
        "--seed",
        "2",
        env_cache=tmp_path / "cache",
    )
    assert done.returncode == 0, done.stderr
    shown = sdt("dataset", "inspect", str(out), "--json", env_cache=tmp_path / "cache")
    assert shown.returncode == 0, shown.stderr
    info = json.loads(shown.stdout)
    recs = info["recordings"]
    for machine, classes in CLASSES.items():
        levels = {(r["condition"], r["run"]) for r in recs if r["machine"] == machine}
        assert {c for c, _ in levels} == set(classes)
        for condition, count in classes.items():
            assert len({run for c, run in levels if c == condition}) == count
    assert {r["channel"] for r in recs} == {"ch1", "ch2", "ch3", "ch4", "ch5"}
    assert len(recs) == 5 * 51 and info["summary"]["skipped"] == 0
    assert {(r["sampling_rate_hz"], r["samples_per_acquisition"]) for r in recs} == {(2e4, 10000)}
    # the files hold the generated signal to 6 significant digits
    ds = open_nln_emp(out, conditions="cavitation suction", channels="ch1", cache=False)
    rec = next(r for r in ds.recordings() if r.run == "cavitation suction 4")
    ref = next(
        r
        for r in open_synthetic(seed=2, duration=0.5).recordings()
        if r.recording_id == rec.recording_id
    )
    np.testing.assert_allclose(rec.load(), ref.load(), rtol=1e-5, atol=1e-9)


def test_inspect_bad_path_is_one_line_error(sdt, tmp_path: Path) -> None:
    done = sdt("dataset", "inspect", str(tmp_path / "nothing.txt"), env_cache=tmp_path)
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert "neither a registered dataset" in done.stderr


def test_list_shows_builtin_datasets(sdt, tmp_path: Path) -> None:
    done = sdt("dataset", "list", "--json", env_cache=tmp_path)
    names = {d["name"]: d["requires_path"] for d in json.loads(done.stdout)}
    assert {"synthetic-pump": False, "nln-emp": True, "manifest": True}.items() <= names.items()
