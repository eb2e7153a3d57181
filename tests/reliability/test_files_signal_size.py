"""One large signal file is sized from its header and refused before it is read.

On main before this round ``sdt degrade``, ``sdt features extract`` and ``sdt
twin check`` read a signal file whole with no estimate: a sparse 9.6 GB
``.npy`` grew past 8 GB of memory (or, under ``ulimit -v``, ended in "out of
memory" after the read had started). Now the samples are read from the
file's header, multiplied by the command's measured bytes per sample
(:mod:`sdt_framework.signals.file_sizes`), and a file that cannot fit in the
memory available is refused in one line naming the file, its samples, the
memory needed and the memory available.

The machine's memory differs from one runner to the next, so the commands
run under an address-space limit (``ulimit -v``, which ``available_memory``
honours): the refusal is hit whatever the machine has. The files are sparse
(``open_memmap`` writes only the header), so no test uses real memory or disk.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.signals.file_sizes import (
    DEGRADE_BYTES_PER_SAMPLE,
    FEATURES_BYTES_PER_SAMPLE,
    TWIN_BYTES_PER_SAMPLE,
    file_samples,
)

from ..helpers import run_sdt

LIMIT = 3 * 2**30  # address space given to the command: enough to start, far from 9.6 GB
SAMPLES = 1_200_000_000  # the file: (1, 1.2e9) float64, 9.6 GB


def run_limited(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """``sdt ARGS`` as a user types it, under ``ulimit -v`` of 3 GiB."""
    return run_sdt(*args, cwd=cwd, env={"SDT_CACHE_DIR": str(cwd / "cache")}, memory_cap=LIMIT)


@pytest.fixture(scope="module")
def huge(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("huge") / "huge.npy"
    array = np.lib.format.open_memmap(path, mode="w+", dtype="float64", shape=(1, SAMPLES))
    del array
    assert path.stat().st_blocks * 512 < 10**6  # sparse: nothing was written but the header
    return path


def refusal(result: subprocess.CompletedProcess[str], name: str, per_sample: int) -> None:
    """One ``error:`` line naming the file, its samples, the memory needed and available."""
    err = result.stderr
    assert result.returncode == 2 and err.count("\n") == 1 and err.startswith("error:"), err
    assert name in err and f"{SAMPLES:,} samples" in err, err
    needed = float(re.search(r"need about ([\d.]+) GB", err)[1])
    assert needed == pytest.approx(SAMPLES * per_sample / 1e9, abs=0.05), err
    available = float(re.search(r"the ([\d.]+) (?:GB|MB) available", err)[1])
    assert available < LIMIT / 1e6, err  # the limit, less what the process already maps
    assert "split it into shorter files" in err or "shorter stretch" in err, err


def test_header_gives_the_samples_of_npy_and_csv(tmp_path: Path, huge: Path, readers) -> None:
    assert file_samples(huge, readers) == SAMPLES
    table = np.random.default_rng(0).normal(size=(5000, 3))
    np.savetxt(tmp_path / "a.csv", table, delimiter=",", header="t,x,y", comments="")
    assert file_samples(tmp_path / "a.csv", readers) == pytest.approx(15000, rel=0.02)
    assert file_samples(tmp_path / "missing.npy", readers) is None


def test_degrade_refuses_a_file_that_cannot_fit(tmp_path: Path, huge: Path) -> None:
    out = tmp_path / "out.npy"
    args = ["degrade", str(huge), "--sensor", "adxl345", "--fs", "20000", "--out", str(out)]
    refusal(run_limited(*args, cwd=tmp_path), str(huge), DEGRADE_BYTES_PER_SAMPLE)
    assert not out.exists()


def test_features_extract_refuses_a_file_that_cannot_fit(tmp_path: Path, huge: Path) -> None:
    out = tmp_path / "f.csv"
    args = ["features", "extract", str(huge), "--fs", "3200", "--out", str(out)]
    refusal(run_limited(*args, cwd=tmp_path), str(huge), FEATURES_BYTES_PER_SAMPLE)
    assert not out.exists()


def test_twin_check_refuses_a_pair_that_cannot_fit(tmp_path: Path, huge: Path) -> None:
    device = tmp_path / "device.npy"
    np.save(device, np.zeros((1, 0)))  # sized 0 samples: the reference is the whole pair
    (tmp_path / "pair.toml").write_text(
        f'[reference]\nfile = "{huge}"\naxes = ["x"]\nrate_hz = 20000\n\n'
        f'[device]\nfile = "device.npy"\naxes = ["x"]\nrate_hz = 3200\n'
    )
    result = run_limited("twin", "check", "pair.toml", "--sensor", "adxl345", cwd=tmp_path)
    refusal(result, "pair.toml", TWIN_BYTES_PER_SAMPLE)


def test_a_file_that_fits_still_runs_under_the_limit(tmp_path: Path) -> None:
    src = tmp_path / "small.npy"
    np.save(src, np.sin(np.arange(40000) / 7.0))
    args = ["degrade", str(src), "--sensor", "adxl345", "--fs", "20000", "--out", "o.npy"]
    result = run_limited(*args, cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    # 40 000 samples at 20 kHz give (40000 - 1) * 3200 / 20000 + 1 samples at 3200 Hz
    assert np.load(tmp_path / "o.npy").shape == (6400,)
