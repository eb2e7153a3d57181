"""A manifest signal that is not real numbers stops the benchmark, naming the file.

On main a bool ``.npy`` was degraded as 0/1 g and a complex one lost its
imaginary part (numpy's ``astype(float)``) while ``sdt degrade`` refused both.
Missing or unreadable files, which are skipped, are now named on the terminal
too (before: only in summary.json).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ..helpers import six_recordings


def _manifest(folder: Path, first: np.ndarray | None) -> Path:
    """Six 2 s recordings, two classes; the first replaced by ``first`` (None: missing)."""
    manifest = six_recordings(folder)
    (folder / "healthy0.npy").unlink()
    if first is not None:
        np.save(folder / "healthy0.npy", first)
    return manifest


@pytest.mark.parametrize(
    ("values", "words"),
    [
        (np.ones(40_000, dtype=bool), "booleans (dtype bool)"),
        (np.ones(40_000) + 1j, "complex numbers (dtype complex128)"),
        (np.array(["1.0"] * 40_000), "text (dtype <U3)"),
        (np.arange(40_000).astype("datetime64[s]"), "dates (dtype datetime64[s])"),
    ],
)
def test_a_signal_of_another_kind_stops_the_benchmark(sdt_main, tmp_path, values, words):
    manifest = _manifest(tmp_path, values)
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", "--data", str(manifest), "--quick", "--out", str(out))
    assert code == 2
    assert err.strip().splitlines() == [
        f"error: {tmp_path / 'healthy0.npy'}: holds {words}, not real numbers; save the signal "
        f"as int or float samples in g (nothing is converted for you) (manifest {manifest} line 2)"
    ]
    assert not out.exists()  # refused before the folder is claimed


def test_integer_counts_are_signals(tmp_path, readers):
    from sdt_framework.signals.files import read_signal

    np.save(tmp_path / "counts.npy", np.arange(-3, 3, dtype=np.int16))
    assert read_signal(tmp_path / "counts.npy", readers, None).tolist() == [[-3, -2, -1, 0, 1, 2]]


def test_a_skipped_file_is_named_on_the_terminal(sdt_main, tmp_path):
    manifest = _manifest(tmp_path, None)
    code, _, err = sdt_main(
        "benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
        "--classifiers", "lr", "--out", str(tmp_path / "out"),
    )  # fmt: skip
    assert code == 0, err
    assert (
        f"skipped {tmp_path / 'healthy0.npy'}: file not found (manifest {manifest} line 2)" in err
    )
