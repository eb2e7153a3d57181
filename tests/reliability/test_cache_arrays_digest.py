"""A parsed-recording cache entry (``cache/arrays``) changed after it was written is refused.

On main the entries were bare ``.npy`` files without a digest: 64 bytes
flipped in every tenth entry (mtime kept) changed 7 of 36 Macro F1 values
with exit 0 and no warning. Now each entry is an ``.npz`` archive (whose
members carry a CRC-32, which catches flipped bytes) holding the array and a
SHA-256 digest of it and its key, as the feature cache's entries do (which
catches an entry rewritten with other samples); a changed or corrupt entry is
named in one ``warning:`` line (not Python's raw ``cache.py:123:
UserWarning`` with its source line), discarded and recomputed, and the
results equal an untouched run's. Run through ``sdt benchmark`` with two
worker processes (``--jobs 2``: a benchmark this short runs in its own process
by default) on a small NLN-EMP tree (CSV files, which is what the array cache
holds): the warnings are raised in the workers.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.data import write_nln_emp

from ..helpers import sdt_here

ARGS = (
    "--quick",
    "--sensors",
    "adxl345",
    "--classifiers",
    "lr",
    "--channels",
    "ch1",
    "--jobs",
    "2",
)


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    root = tmp_path / "pump"
    write_nln_emp(open_synthetic(duration=1.5, channels="ch1"), root)
    return root


def _flip(entry: Path, offset: int, count: int = 64) -> None:
    """Invert ``count`` bytes of ``entry`` from ``offset`` on, keeping its size and mtime."""
    stat = entry.stat()
    data = bytearray(entry.read_bytes())
    data[offset : offset + count] = bytes(b ^ 0xFF for b in data[offset : offset + count])
    entry.write_bytes(bytes(data))
    os.utime(entry, ns=(stat.st_atime_ns, stat.st_mtime_ns))


def _tamper(entry: Path) -> None:
    """Store other samples (doubled) under the entry's old digest, as a valid archive."""
    with np.load(entry) as stored:
        arrays = {name: stored[name] for name in stored.files}
    arrays["data"] = arrays["data"] * 2
    with entry.open("wb") as handle:
        np.savez(handle, **arrays)


def _results(folder: Path) -> pd.DataFrame:
    return pd.read_csv(folder / "results.csv").drop(columns="fit_seconds")


def test_changed_and_corrupt_array_entries_are_named_and_recomputed(sdt, tree, tmp_path):
    cache = tmp_path / "cache"  # the sdt fixture's SDT_CACHE_DIR
    env = {"SDT_CACHE_DIR": str(cache)}
    # the untouched run and the last one in this process: only the one meeting the damaged
    # entries is the subject, run as a user runs it (its stderr as the terminal shows it)
    first = sdt_here(
        "benchmark", "--data", str(tree), *ARGS, "--no-report", "--out", str(tmp_path / "a"),
        env=env,
    )  # fmt: skip
    assert first.returncode == 0, first.stderr
    entries = sorted((cache / "arrays").iterdir())
    assert len(entries) >= 10 and all(e.suffix == ".npz" for e in entries)
    flipped = entries[::10]
    for entry in flipped:  # inside the stored samples: the file keeps its size and mtime
        with np.load(entry) as stored:
            assert stored["data"].nbytes > 1000
        _flip(entry, entry.stat().st_size // 2)
    _tamper(entries[1])  # a valid archive with other samples and the old digest
    entries[2].write_bytes(entries[2].read_bytes()[:100])  # not an archive any more
    features = cache / "features"
    for block in features.rglob("*.npz"):  # make the benchmark read the recordings again
        block.unlink()

    again = sdt(
        "benchmark", "--data", str(tree), *ARGS, "--no-report", "--out", str(tmp_path / "b")
    )
    assert again.returncode == 0, again.stderr
    warned = [line for line in again.stderr.splitlines() if line.startswith("warning: cache entry")]
    named = {re.search(r"arrays/(\w+)\.npz", line)[1] for line in warned}
    assert named == {e.stem for e in [*flipped, entries[1], entries[2]]}
    assert len(warned) == len(named)  # one line each
    assert sum("its checksum does not match" in line for line in warned) == 1
    assert sum("is corrupt" in line for line in warned) == len(flipped) + 1
    assert "Warning:" not in again.stderr and ".py:" not in again.stderr  # no raw Python warning
    pd.testing.assert_frame_equal(_results(tmp_path / "b"), _results(tmp_path / "a"))
    assert all(e.exists() for e in entries)  # rewritten, and read cleanly next time
    third = sdt_here(
        "benchmark", "--data", str(tree), *ARGS, "--no-report", "--out", str(tmp_path / "b"),
        env=env,
    )  # fmt: skip
    assert third.returncode == 0 and "warning: cache entry" not in third.stderr
