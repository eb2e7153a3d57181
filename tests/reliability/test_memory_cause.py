"""Out of memory names what was being built; a device given as a file is refused unread.

On main before round 2 every MemoryError ended in "process less data at once
(shorter or fewer recordings, fewer --jobs)", whatever ran out: a huge sweep
design, or ``/dev/zero`` given as a sensor file, config or sweep (read until
memory ran out). The /dev/zero cases run in a child process whose address
space is capped at 3 GiB, so that on old code they end in a MemoryError
instead of taking the machine's memory.
"""

from __future__ import annotations

import subprocess
import textwrap
from pathlib import Path
from types import SimpleNamespace

import pytest

from ..helpers import run_sdt
from .conftest import without_estimate

CAP = 3 * 2**30


def _sdt(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    env = {"SDT_CACHE_DIR": str(cwd / "cache")}
    return run_sdt(*args, cwd=cwd, env=env, memory_cap=CAP, timeout=120)


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero")
@pytest.mark.parametrize(
    ("args", "named"),
    [
        (["--sensor-file", "zero.toml", "sensors", "list"], "sensor file zero.toml"),
        (["benchmark", "/dev/zero", "--out", "out"], "config file /dev/zero"),
        (["explore", "zero.toml", "--out", "out"], "sweep file zero.toml"),
        (
            ["degrade", "zero.npy", "--sensor", "adxl345", "--fs", "20000", "--out", "x.npy"],
            "signal file zero.npy",
        ),
        # the plan opens --data by its absolute path (workers in other folders open the same)
        (["benchmark", "--data", "zero.csv", "--out", "out"], "manifest {tmp}/zero.csv"),
    ],
)
def test_a_device_given_as_a_file_is_refused_unread(tmp_path, args, named):
    for name in ("zero.toml", "zero.npy", "zero.csv"):
        (tmp_path / name).symlink_to("/dev/zero")
    result = _sdt(*args, cwd=tmp_path)
    assert result.returncode == 2
    named = named.format(tmp=tmp_path)
    assert result.stderr == (
        f"error: {named}: not a regular file (a character device); give the path of a file\n"
    )
    assert not (tmp_path / "out").exists() and not (tmp_path / "x.npy").exists()


SWEEP = """
[sweep]
base = "adxl345"
[sweep.axes]
noise_density_ug_rthz = { levels = [90, 290] }
full_scale_g = { levels = [2, 16] }
[benchmark]
machines = ["Motor-2"]
"""


def _no_memory(*args, **kwargs):
    raise MemoryError("Unable to allocate 7.45 GiB for an array with shape (1000000000,)")


def test_memory_running_out_in_the_design_names_the_design(sdt_main, tmp_path, monkeypatch):
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(textwrap.dedent(SWEEP))
    # the grid's combinations are where a grid's memory goes
    monkeypatch.setattr(
        "sdt_framework.explore.design.itertools", SimpleNamespace(product=_no_memory)
    )
    code, _, err = sdt_main("explore", str(sweep), "--quick", "--out", str(tmp_path / "out"))
    assert code == 2 and err.count("\n") == 1
    assert err == (
        "error: out of memory while building the grid design of 4 points (Unable to allocate "
        "7.45 GiB for an array with shape (1000000000,)); use fewer levels, steps or samples, "
        "or use a machine with more memory\n"
    )
    assert not (tmp_path / "out").exists()


def test_memory_running_out_in_the_benchmark_names_its_size(sdt_main, tmp_path, monkeypatch):
    monkeypatch.setattr("sdt_framework.bench.runner.run_benchmark", _no_memory)
    args = ["benchmark", "--quick", "--machines", "Motor-2", "--sensors", "adxl345"]
    code, _, err = sdt_main(*args, "--classifiers", "lr", "--out", str(tmp_path / "out"))
    err = without_estimate(err)
    assert code == 2 and err.count("\n") == 1
    # 3 scenarios x 2 repeats; 75 Motor-2 recordings x 2 noisy draws
    assert err.startswith(
        "error: out of memory while running the benchmark (6 runs and 150 featurised signals, "
    )
    assert err.rstrip().endswith(
        "process less data at once (shorter or fewer recordings, fewer --jobs), "
        "or use a machine with more memory"
    )


def test_memory_running_out_elsewhere_blames_no_recordings(sdt_main, monkeypatch):
    monkeypatch.setattr("sdt_framework.cli.sensors.registry", _no_memory)
    code, _, err = sdt_main("sensors", "list")
    assert code == 2 and err.count("\n") == 1
    assert err.startswith("error: out of memory (Unable to allocate 7.45 GiB")
    assert "recordings" not in err and "ask for less data at once" in err
