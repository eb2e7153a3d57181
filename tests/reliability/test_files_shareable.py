"""Shareable outputs hold no absolute path of the author's machine and no platform string.

On main, ``config.toml``, ``sweep.toml``, ``report.md``/``.html`` and ``summary.json``
carried the data's absolute path and the platform string (kernel, libc). Now
paths are written relative to the results folder, machine details sit only in
``summary.json["machine"]``, and the folder still resumes: from another working
directory, and after the folder and its data are moved together.

The commands run in this process (``sdt_in_process``, ``--jobs 1``: no worker starts; the
results are the same at any ``--jobs``), each from its working directory (``chdir``): the
paths are the subject, not the process.
"""

from __future__ import annotations

import json
import platform
import shutil
from pathlib import Path

import pytest

from ..helpers import six_recordings

SHAREABLE = ("config.toml", "report.md", "report.html", "summary.json")


def _manifest(folder: Path) -> Path:
    """Six 2 s noise recordings (two classes) and their manifest, paths relative to it."""
    folder.mkdir()
    return six_recordings(folder, "manifest.csv")


@pytest.fixture
def sdt_from(sdt_in_process, monkeypatch):
    """``sdt_from(*args, cwd=..., cache=...)``: ``sdt ARGS --jobs 1`` run from ``cwd``, here."""

    def run(*args: str, cwd: Path | str, cache: Path):
        monkeypatch.chdir(cwd)
        done = sdt_in_process(*args, "--jobs", "1", env={"SDT_CACHE_DIR": str(cache)})
        assert done.returncode == 0, done.stderr
        return done

    return run


def _leaks(folder: Path, secret: str) -> list[str]:
    found = []
    for name in SHAREABLE:
        text = (folder / name).read_text(encoding="utf-8")
        if name == "summary.json":
            data = json.loads(text)
            assert data["machine"]["platform"] == platform.platform()
            text = json.dumps({k: v for k, v in data.items() if k != "machine"})
        found += [f"{name}: {secret}" for s in (secret,) if s in text]
        found += [f"{name}: platform" for p in (platform.platform(),) if p in text]
    return found


def test_a_results_folder_names_no_absolute_path_and_resumes_when_moved(sdt_from, tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    manifest = _manifest(home / "pump")
    cache = tmp_path / "cache"
    args = ["--sensors", "adxl345", "--classifiers", "lr", "--quick"]
    sdt_from("benchmark", "--data", str(manifest), *args, "--out", "results", cwd=home, cache=cache)
    out = home / "results"
    assert _leaks(out, str(tmp_path)) == []
    assert 'data = "../pump/manifest.csv"' in (out / "config.toml").read_text()

    # resumed from its own config.toml, from another working directory
    again = sdt_from("benchmark", str(out / "config.toml"), "--out", str(out), cwd="/", cache=cache)
    assert "(0 computed, 6 resumed, 0 failed)" in again.stdout

    # the folder and its data moved together: it runs again, with the same numbers
    moved = tmp_path / "elsewhere"
    shutil.copytree(home, moved)
    sdt_from("benchmark", "results/config.toml", "--out", "results", cwd=moved, cache=cache)
    before = (out / "table4.md").read_text()
    assert (moved / "results" / "table4.md").read_text() == before


def test_an_exploration_writes_its_sweep_with_relative_paths(sdt_from, tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    manifest = _manifest(home / "pump")
    sweep = home / "sweep.toml"
    sweep.write_text(
        '[sweep]\nbase = "adxl345"\ntarget = { max_loss = 0.1 }\n'
        "[sweep.axes.noise_density_ug_rthz]\nlevels = [90, 290]\n"
        f'[benchmark]\ndata = "{manifest.as_posix()}"\nclassifiers = ["lr"]\nrepeats = 1\n'
        'scenarios = ["forward"]\n',
        encoding="utf-8",
    )
    cache = tmp_path / "cache"
    exhaustive = ("--strategy", "exhaustive")  # the strategy whose folder holds sweep.toml
    sdt_from(
        "explore",
        str(sweep),
        "--out",
        "explored",
        "--no-report",
        *exhaustive,
        cwd=home,
        cache=cache,
    )
    written = (home / "explored" / "sweep.toml").read_text(encoding="utf-8")
    assert str(tmp_path) not in written
    assert 'data = "../pump/manifest.csv"' in written
    again = sdt_from(
        "explore",
        "explored/sweep.toml",
        "--out",
        "explored",
        "--no-report",
        *exhaustive,
        cwd=home,
        cache=cache,
    )
    assert "runs (0 still to do)" in again.stdout, again.stdout
