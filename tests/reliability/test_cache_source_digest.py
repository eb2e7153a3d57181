"""A data file corrected with its size and mtime kept is read again, not served from cache.

On main the feature cache (and the parsed-array cache of NLN-EMP CSV files)
knew a file by its path, size and modification time: a corrected DAQ export of
the same size copied over the old one with its mtime (``cp -p``, ``rsync -a``)
was served the old features with exit 0 and no word. Now a file is known by
the digest of its bytes (remembered per inode and change time, which no copy
can set back), so the second run equals one with a fresh cache.
"""

from __future__ import annotations

import os
import shutil
import time
from pathlib import Path

import pandas as pd
import pytest
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.data import write_nln_emp
from sdt_framework.data.digest import SETTLE_NS

ARGS = ["--quick", "--sensors", "wilcoxon-786b10", "--classifiers", "lr", "--no-report"]
ARGS += ["--jobs", "1"]  # the same features at any --jobs (test_bench_jobs.py); no worker

#: the cache, not workers, is the subject: ``sdt`` runs in this process (conftest.py), where
#: nothing a run keeps in memory may serve the corrected file either
pytestmark = pytest.mark.in_process


def _correct(csv: Path, scratch: Path) -> None:
    """Rewrite ``csv`` with other samples (every digit 3 of a sample made 4, the time column
    kept: same size), as a corrected export copied over it with ``cp -p`` (mtime kept)."""
    header, *rows = csv.read_text(encoding="utf-8").splitlines(keepends=True)
    fixed = scratch / csv.name
    samples = [row.partition(",") for row in rows]
    fixed.write_text(
        header + "".join(t + c + s.replace("3", "4") for t, c, s in samples), encoding="utf-8"
    )
    os.utime(fixed, ns=(csv.stat().st_atime_ns, csv.stat().st_mtime_ns))
    before = csv.stat()
    shutil.copy2(fixed, csv)  # what cp -p does
    after = csv.stat()
    assert (after.st_size, after.st_mtime_ns) == (before.st_size, before.st_mtime_ns)


def _features(folder: Path) -> pd.DataFrame:
    return pd.read_parquet(folder / "features.parquet")


def test_a_corrected_file_of_the_same_size_and_mtime_is_read_again(sdt, tmp_path):
    root = tmp_path / "pump"
    write_nln_emp(open_synthetic(duration=1.5, machines="Motor-2", channels="ch1"), root)
    # the files settle (a digest is remembered only then), as a real process's start gave them:
    # the first run remembers the old files' digests, which must not serve the corrected ones
    time.sleep(SETTLE_NS / 1e9 + 0.2)
    cache = tmp_path / "cache"  # the sdt fixture's SDT_CACHE_DIR
    first = sdt("benchmark", "--data", str(root), *ARGS, "--out", str(tmp_path / "a"))
    assert first.returncode == 0, first.stderr
    faults = sorted(p for p in root.rglob("*.csv") if "healthy" not in p.parent.name)
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    for csv in faults:
        _correct(csv, scratch)

    again = sdt("benchmark", "--data", str(root), *ARGS, "--out", str(tmp_path / "b"))
    assert again.returncode == 0, again.stderr
    fresh = sdt(
        "benchmark", "--data", str(root), *ARGS, "--out", str(tmp_path / "c"),
        env={"SDT_CACHE_DIR": str(tmp_path / "fresh-cache")},
    )  # fmt: skip
    assert fresh.returncode == 0, fresh.stderr
    pd.testing.assert_frame_equal(_features(tmp_path / "b"), _features(tmp_path / "c"))
    changed = _features(tmp_path / "a").ne(_features(tmp_path / "b")).any(axis=1)
    # the corrected recordings' windows, and only those, have other features
    corrected = {f"Motor-2/{p.parent.parent.name}/{p.parent.name}/ch1" for p in faults}
    rows = _features(tmp_path / "b")
    assert set(rows.loc[changed, "recording_id"]) == corrected
    assert (cache / "digests").is_dir()  # the digests are remembered for the next run
