"""A rate a file states is bounded, and a file cut inside its header is named (issue 39, item 6).

On main a WAV whose header says 0 Hz was listed at 0 Hz by ``inspect``, crashed a manifest
giving a rate (``ZeroDivisionError`` in ``reconcile``) and was taken as a 0 Hz recording by
one leaving it empty; a WAV cut inside its header gave ``struct.error``, one with zero
frames a ``reshape`` error, both "internal error"; a TDMS channel with ``wf_increment =
1e6`` (1e-6 Hz) crashed the benchmark's estimate with ``ZeroDivisionError``. Every rate a
reader takes from a file is now held to 25 Hz to 10 MHz, the twin's range, shared.
"""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest
import scipy.io.wavfile

from sdt_framework.signals.files import read_signal

from ..helpers import six_recordings

HEADER = "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
RANGE = "outside 25 Hz to 10 MHz, the rates sdt reads"


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def _wav(file: Path, rate: int = 25_600, frames: int = 4096, channels: int = 1) -> Path:
    """A float WAV written by scipy, its header's sample rate then set to ``rate``."""
    scipy.io.wavfile.write(file, 25_600, np.zeros((frames, channels), dtype=np.float32))
    data = bytearray(file.read_bytes())
    assert data[12:16] == b"fmt " and struct.unpack("<I", data[24:28]) == (25_600,)
    data[24:28] = struct.pack("<I", rate)  # nSamplesPerSec of the fmt chunk
    file.write_bytes(bytes(data))
    return file


def _tdms(file: Path, channels: dict[str, float]) -> Path:
    from nptdms import ChannelObject, TdmsWriter

    objects = [
        ChannelObject(group, name, np.zeros(4096), properties={"wf_increment": step})
        for (group, name), step in ((key.split("/"), step) for key, step in channels.items())
    ]
    with TdmsWriter(file) as writer:
        writer.write_segment(objects)
    return file


def test_a_wav_header_rate_of_0_hz_is_refused_naming_the_field(sdt_main, tmp_path):
    code, _, err = sdt_main("dataset", "inspect", str(_wav(tmp_path / "rec.wav", rate=0)))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {tmp_path / 'rec.wav'}: its header's sample rate (fmt chunk) is 0 Hz, {RANGE}; "
        f"the header is damaged or was written with a wrong rate; export the file again at the "
        f"recorder's rate"
    )


@pytest.mark.parametrize("rate_column", ["", "20000"])
def test_a_manifest_row_of_a_0_hz_wav_is_skipped_with_the_reason(sdt_main, tmp_path, rate_column):
    _wav(tmp_path / "rec.wav", rate=0)
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"{HEADER}rec.wav,{rate_column},healthy,,r1,ch1\n", encoding="utf-8")
    code, out, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 0, err
    assert "its header's sample rate (fmt chunk) is 0 Hz" in out
    assert "0 recordings in 0 runs" in out and "1 skipped" in out


@pytest.mark.parametrize("keep", [16, 20, 30, 40, 50])
def test_a_wav_cut_inside_its_header_is_named_truncated(sdt_main, tmp_path, keep):
    whole = _wav(tmp_path / "whole.wav").read_bytes()
    cut = tmp_path / "cut.wav"
    cut.write_bytes(whole[:keep])
    code, _, err = sdt_main("dataset", "inspect", str(cut))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {cut}: truncated: the file holds {keep} bytes, its RIFF header declares "
        f"{len(whole):,}; copy it from the recorder again"
    )


@pytest.mark.parametrize(("dtype", "channels"), [(np.float32, 1), (np.int16, 2)])
def test_a_wav_with_zero_frames_holds_no_samples(sdt_main, tmp_path, dtype, channels):
    file = tmp_path / "empty.wav"
    scipy.io.wavfile.write(file, 25_600, np.zeros((0, channels), dtype=dtype))
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: signal 'ch1' holds no samples (an empty recording); give a file with data"
    )


def test_a_tdms_channel_at_a_microhertz_rate_is_refused_naming_wf_increment(sdt_main, tmp_path):
    file = _tdms(tmp_path / "slow.tdms", {"g/c": 1e6})
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: its channel 'g/c' wf_increment is 1e+06 s, a rate of 1e-06 Hz, {RANGE}; "
        f"check that field (a time step in seconds)"
    )


def test_a_microhertz_tdms_row_is_skipped_and_the_benchmark_runs(sdt_main, tmp_path):
    """On main: internal error, ZeroDivisionError in the benchmark's estimate."""
    manifest = six_recordings(tmp_path)
    _tdms(tmp_path / "healthy0.tdms", {"g/c": 1e6})
    text = manifest.read_text(encoding="utf-8").replace("healthy0.npy,20000", "healthy0.tdms,")
    manifest.write_text(text, encoding="utf-8")
    code, _, err = sdt_main(
        "benchmark", "--data", str(manifest), "--quick", "--sensors", "adxl345",
        "--classifiers", "lr", "--jobs", "1", "--no-report", "--out", str(tmp_path / "out"),
    )  # fmt: skip
    assert code == 0, err
    assert "internal error" not in err
    assert (
        f"skipped {tmp_path / 'healthy0.tdms'}: {tmp_path / 'healthy0.tdms'}: its channel 'g/c' "
        f"wf_increment is 1e+06 s, a rate of 1e-06 Hz, {RANGE}"
    ) in err


def test_a_slow_channel_beside_an_accelerometer_is_listed_with_a_warning(
    sdt_main, tmp_path, readers
):
    """A 1 Hz temperature channel does not hide the accelerometer of the same file; reading
    it is refused with the same line."""
    file = _tdms(tmp_path / "daq.tdms", {"acc/x": 1 / 25_600, "env/temp": 1.0})
    code, out, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    assert "acc/x" in out and "env/temp" in out
    fault = f"{file}: its channel 'env/temp' wf_increment is 1 s, a rate of 1 Hz, {RANGE}"
    assert f"warning: listed, not read: {fault}" in err
    assert read_signal(file, readers, "acc/x").shape == (1, 4096)
    with pytest.raises(Exception, match=fault.replace("(", r"\(").replace(")", r"\)")):
        read_signal(file, readers, "env/temp")


def test_the_readers_and_the_twin_hold_rates_to_one_range():
    from sdt_framework.signals import rules as readers
    from sdt_framework.twin import pair

    assert readers.RATE_RANGE_HZ == (25.0, 1e7)
    assert pair.RATE_RANGE_HZ is readers.RATE_RANGE_HZ
