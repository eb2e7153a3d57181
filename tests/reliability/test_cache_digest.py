"""A feature-cache entry changed after it was written is detected, discarded and recomputed.

On main a tampered entry of the right shape (the values edited, the arrays
intact) was served from a shared cache and changed every result silently.
"""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import numpy as np
import pandas as pd

from sdt_framework.bench.feature_cache import ChecksumMismatchError, read_entry, write_entry
from sdt_framework.bench.plan import plan_benchmark
from sdt_framework.bench.runner import run_benchmark


def _tamper(entry: Path) -> None:
    """Scale the stored feature values by 2, keeping every array's name, shape and dtype."""
    with np.load(entry, allow_pickle=False) as stored:
        arrays = {name: stored[name] for name in stored.files}
    arrays["values"] = (arrays["values"] * 2).astype(np.float32)
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)
    entry.write_bytes(buffer.getvalue())


def test_read_entry_refuses_changed_contents(tmp_path):
    path = tmp_path / "e.npz"
    arrays = (
        np.ones((3, 8), np.float32),
        np.zeros(3, np.int64),
        np.arange(3),
        np.array([0, 10], np.int64),
    )
    write_entry(path, "key", arrays)
    assert all(
        np.array_equal(a, b) for a, b in zip(read_entry(path, "key", 8), arrays, strict=True)
    )
    _tamper(path)
    with zipfile.ZipFile(path) as archive:
        assert sorted(archive.namelist()) == [
            "acquisition.npy", "counts.npy", "digest.npy", "values.npy", "window.npy",
        ]  # fmt: skip
    try:
        read_entry(path, "key", 8)
    except ChecksumMismatchError:
        pass
    else:
        raise AssertionError("a changed entry was accepted")


def test_a_tampered_cache_changes_no_result(small_config, registry, tmp_path):
    config = small_config()
    clean = run_benchmark(plan_benchmark(config, registry), tmp_path / "clean")
    entries = sorted((Path(config.cache_dir) / "features").rglob("*.npz"))
    assert entries
    for entry in entries:
        _tamper(entry)
    warnings: list[str] = []
    again = run_benchmark(
        plan_benchmark(config, registry), tmp_path / "again", warn=warnings.append
    )
    assert again.features_cached == 0  # every tampered entry refused
    assert len(warnings) == len(entries)
    assert all("checksum does not match" in w for w in warnings)
    pd.testing.assert_frame_equal(again.features, clean.features)
    assert [r.macro_f1 for r in again.runs] == [r.macro_f1 for r in clean.runs]
