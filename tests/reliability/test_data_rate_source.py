"""A benchmark's error about a recording names its file and where its rate came from (issue 39,
weak items).

On main, a recording too short for one window (an LVM among longer files, past the plan's
check of one recording per rate) stopped the benchmark with "acquisitions of 1280 samples are
too short" and no file; a feature band left empty by a WAV header's rate said "check the
sampling rate given (--fs)", an option the benchmark does not have.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.io.wavfile

from sdt_framework import FeatureSetSpec, SDTError
from sdt_framework.bench.featurise import FeatureJob, featurise_recording
from sdt_framework.data.manifest import open_manifest
from sdt_framework.specs import FeatureBand

from ..helpers import six_recordings
from .labview import lvm, segment


def test_a_band_the_file_rate_leaves_empty_names_the_file_and_its_rate(tmp_path, registry, readers):
    """A 400 Hz WAV (rate from its header) and a feature set of 1-2 kHz: no FFT bin."""
    wav = tmp_path / "rec.wav"
    scipy.io.wavfile.write(wav, 400, np.random.default_rng(0).normal(size=1600).astype("f4"))
    (tmp_path / "m.csv").write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\nrec.wav,,healthy,,r1,ch1\n",
        encoding="utf-8",
    )
    [recording] = open_manifest(tmp_path / "m.csv", readers=readers).recordings()
    assert recording.sampling_rate_hz == 400.0  # the header's rate
    high = FeatureSetSpec(
        name="high",
        feature_names=("a",),
        units=("g",),
        compute=lambda w, fs: w[:, :1],
        bands=(FeatureBand(features=("a",), low_hz=1000, high_hz=2000),),
    )
    native = registry.sensor("native-reference")
    job = FeatureJob(recording, "k", (native,), high, 1, 0, 0.64, 0.1, None, "x")
    with pytest.raises(SDTError) as info:
        featurise_recording(job)
    message = str(info.value)
    assert message.startswith(f"{wav} (machine/r1/ch1): feature set 'high': the band 1000")
    assert "fs=400 Hz" in message
    assert message.endswith(
        "check the file's rate (its header's, or the manifest's sampling_rate_hz)"
    )
    assert "--fs" not in message


def test_a_short_lvm_recording_is_named_when_it_stops_the_benchmark(
    sdt_main, tmp_path, monkeypatch
):
    """Five 2 s recordings and, last, an LVM of 0.064 s (1280 samples at 20 kHz): with the
    plan's length check off (it refuses the file first, test_bench_worker_errors.py), the
    worker meets the short one and its error names the file."""
    monkeypatch.setattr("sdt_framework.bench.plan.check_lengths", lambda *a: None, raising=False)
    manifest = six_recordings(tmp_path)
    rows = np.round(np.random.default_rng(0).normal(size=(1280, 1)), 6)
    short = tmp_path / "fault2.lvm"
    short.write_text(lvm([segment(["acc"], rows, 1 / 20_000)]), encoding="utf-8")
    text = manifest.read_text(encoding="utf-8").replace("fault2.npy,20000", "fault2.lvm,")
    manifest.write_text(text, encoding="utf-8")
    assert text.rstrip().splitlines()[-1].startswith("fault2.lvm,")
    code, _, err = sdt_main(
        "benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
        "--classifiers", "lr", "--jobs", "1", "--no-report", "--out", str(tmp_path / "out"),
    )  # fmt: skip
    assert code == 2
    [line] = [line for line in err.splitlines() if line.startswith("error: ")]
    # at 3200 Hz the ADXL345 samples at k / 3200 s < 0.064 s: k = 0..204, 205 samples
    assert line.startswith(
        f"error: {short} (m/fault2/ch1): acquisitions of 205 samples are too short: one window "
        f"at 3200 Hz needs"
    )
