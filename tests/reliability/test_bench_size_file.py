"""A recording too large to process is named, with its size, instead of "fewer repeats".

On main a manifest holding one 50 GB ``.npy`` (a sparse file: no disk used)
was refused with "needs about 3.3 TB of memory ...; lower --repeats or select
fewer sensors, classifiers or machines", advice that cannot help: one
recording alone needs more memory than the machine has. Now the refusal
names the recording, its file and size, and what helps (shorter recordings).
"""

from __future__ import annotations

import numpy as np
import pytest

from ..helpers import six_recordings

#: refused before any recording is read or worker started: ``sdt`` runs in this process
pytestmark = pytest.mark.in_process

SAMPLES = 6_250_000_000  # float64: 50 GB


def test_a_recording_too_large_for_memory_is_named_with_its_size(sdt, tmp_path):
    manifest = six_recordings(tmp_path)
    np.lib.format.open_memmap(  # replaces healthy0 with a sparse 50 GB file
        tmp_path / "healthy0.npy", mode="w+", dtype=np.float64, shape=(1, SAMPLES)
    ).flush()
    assert (tmp_path / "healthy0.npy").stat().st_size > 50e9
    out = tmp_path / "out"

    done = sdt("benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
               "--classifiers", "lr", "--out", str(out))  # fmt: skip
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    line = lines[0]
    assert line.startswith("error: this benchmark cannot run: recording m/healthy0/ch1 (")
    assert f"{tmp_path / 'healthy0.npy'}, 50.0 GB) is 6,250,000,000 samples" in line
    assert "split it into shorter recordings" in line
    assert "--repeats" not in line
    assert not out.exists()
