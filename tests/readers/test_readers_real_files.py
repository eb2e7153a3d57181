"""Each built-in reader on real files from its library's own test data (tests/data/readers).

Every rate, unit and value is checked against a figure computed here without
the reader under test: header bytes parsed with ``struct``, text parsed by
hand, a signal the file's own label names (a 5 Hz sine), or the library's own
published test expectation.
"""

from __future__ import annotations

import struct
import wave
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import reader_for, scan_file

DATA = Path(__file__).parents[1] / "data" / "readers"


def _read(registry, file: Path, variable: str | None = None, **options) -> np.ndarray:
    return reader_for(file, registry.signal_readers()).read(file, variable, **options)


def _wav_data_chunk(file: Path) -> tuple[int, int, bytes]:
    """(rate, bits per sample, data bytes) of a RIFF WAVE file, by walking its chunks."""
    raw = file.read_bytes()
    pos, rate, bits = 12, 0, 0
    while pos + 8 <= len(raw):
        tag, size = raw[pos : pos + 4], struct.unpack("<I", raw[pos + 4 : pos + 8])[0]
        if tag == b"fmt ":
            rate = struct.unpack("<I", raw[pos + 12 : pos + 16])[0]
            bits = struct.unpack("<H", raw[pos + 22 : pos + 24])[0]
        if tag == b"data":
            return rate, bits, raw[pos + 8 : pos + 8 + size]
        pos += 8 + size + (size & 1)
    raise AssertionError("no data chunk")


def test_tdms_daqmx_raw_file_rate_units_and_scaling(registry):
    """npTDMS's raw1.tdms: 7 NI-DAQmx channels, 2000 samples at wf_increment 2e-5 s, Volts."""
    from nptdms import TdmsFile

    file = DATA / "raw1.tdms"
    reader, infos = scan_file(file, registry.signal_readers())
    assert reader.name == "tdms"
    assert len(infos) == 7
    first = infos[0]
    assert first.variable == "Layer Data/First  Channel"
    assert first.rate_hz == pytest.approx(50_000.0, rel=1e-12)
    assert first.units == "Volts" and first.n_samples == 2000
    raw = TdmsFile.read(file)["Layer Data"]["First  Channel"].read_data(scaled=False)[0]  # scaler 0
    slope = 0.0003051850947599719  # NI_Scale[1]_Linear_Slope of the channel (int16 -> volts)
    np.testing.assert_allclose(_read(registry, file, first.variable)[0], raw * slope, rtol=1e-12)


def test_tdms_written_by_nptdms_at_25_6_khz_in_g(registry, tmp_path):
    from nptdms import ChannelObject, TdmsWriter

    t = np.arange(2560) / 25_600.0
    signal = 0.5 * np.sin(2 * np.pi * 160.0 * t)
    file = tmp_path / "run.tdms"
    props = {"wf_increment": 1 / 25_600, "unit_string": "g", "wf_start_offset": 0.0}
    with TdmsWriter(file) as writer:
        writer.write_segment([ChannelObject("acc", "pump-DE", signal, properties=props)])
    (info,) = scan_file(file, registry.signal_readers())[1]
    assert (info.variable, info.rate_hz, info.units) == ("acc/pump-DE", 25_600.0, "g")
    np.testing.assert_array_equal(_read(registry, file)[0], signal)


def test_uff58_binary_is_the_sine_its_label_names(registry):
    """pyuff's binary8byte.uff: 'sine 5 Hz', 250 points, abscissa_inc 0.01 s, in g."""
    file = DATA / "binary8byte.uff"
    (info,) = scan_file(file, registry.signal_readers())[1]
    assert (info.variable, info.n_samples, info.units) == ("1", 250, "g")
    assert info.rate_hz == pytest.approx(100.0)
    t = np.arange(250) * 0.01
    # the file was computed in float32: a phase of up to 2*pi*12.5 rad carries ~1e-5 rad of error
    np.testing.assert_allclose(_read(registry, file)[0], np.sin(2 * np.pi * 5 * t), atol=2e-5)


def test_uff58_ascii_and_binary_exports_of_one_recording_agree(registry):
    """pyuff's Sample_UFF58 pair: one microphone record exported as ASCII and as binary 58b."""
    ascii_file, binary_file = DATA / "Sample_UFF58_ascii.uff", DATA / "Sample_UFF58b_bin.uff"
    (a,) = scan_file(ascii_file, registry.signal_readers())[1]
    (b,) = scan_file(binary_file, registry.signal_readers())[1]
    assert a.n_samples == b.n_samples == 79_292
    assert a.rate_hz == b.rate_hz == pytest.approx(1 / 1.52588e-05)  # 65.536 kHz, 6 digits
    assert a.units == b.units == "Pa"
    x, y = _read(registry, ascii_file)[0], _read(registry, binary_file)[0]
    # the ASCII export keeps 6 significant digits (E13.5)
    np.testing.assert_allclose(x, y, rtol=0, atol=5e-6 * np.abs(y).max())


def test_lvm_short_file_against_its_text(registry):
    """lvm_read's short.lvm: Delta_X 3.90625E-5 s (25.6 kHz), comma decimals, two channels."""
    file = DATA / "short.lvm"
    infos = scan_file(file, registry.signal_readers())[1]
    assert [i.variable for i in infos] == ["Excitation (Trigger)", "Response (Trigger)"]
    assert [i.units for i in infos] == ["Newtons", "m/s^2"]
    assert all(i.rate_hz == 25_600.0 and i.n_samples == 10 for i in infos)
    text = file.read_text(encoding="utf-8").splitlines()
    start = text.index(next(line for line in text if line.startswith("X_Value"))) + 1
    rows = [line.split("\t") for line in text[start:] if line.strip()]
    response = np.array([float(r[2].replace(",", ".")) for r in rows])
    np.testing.assert_array_equal(_read(registry, file, "Response (Trigger)")[0], response)


def test_matlab_v73_file_written_by_matlab(registry):
    """mat7.3's testfile1.mat (MATLAB on PCWIN64): numeric 'secondvar' = [1 2 3 4]; the char
    'keys' is listed as no signal; the struct 'data' is read field by field
    (tests/reliability/test_data_matlab_files.py)."""
    file = DATA / "testfile1.mat"
    reader, infos = scan_file(file, registry.signal_readers())
    assert reader.name == "mat73"
    by_name = {i.variable: i for i in infos}
    assert by_name["secondvar"].shape == (1, 4) and by_name["secondvar"].fault is None
    assert "variable 'keys' is a MATLAB char, not an array of numbers" in by_name["keys"].fault
    np.testing.assert_array_equal(_read(registry, file, "secondvar")[0], [1.0, 2.0, 3.0, 4.0])


def test_matlab_v73_written_with_h5py_and_v5_side_by_side(registry, tmp_path):
    """A v7.3 file (HDF5 behind MATLAB's 512-byte header) and a v5 one share '.mat'."""
    import h5py
    import scipy.io

    signal = np.sin(np.arange(3 * 4096).reshape(3, 4096) / 7.0)
    v73 = tmp_path / "v73.mat"
    with h5py.File(v73, "w", userblock_size=512) as handle:
        handle.create_dataset("acc", data=signal)  # MATLAB's 4096x3 column-major matrix
        handle["acc"].attrs["MATLAB_class"] = np.bytes_("double")
    with open(v73, "r+b") as handle:
        handle.write(b"MATLAB 7.3 MAT-file, Platform: GLNXA64, HDF5 schema 1.00 .".ljust(116))
    v5 = tmp_path / "v5.mat"
    scipy.io.savemat(v5, {"acc": signal.T})
    assert reader_for(v73, registry.signal_readers()).name == "mat73"
    assert reader_for(v5, registry.signal_readers()).name == "mat"
    np.testing.assert_array_equal(_read(registry, v73), signal)
    np.testing.assert_array_equal(_read(registry, v5), signal)


def test_wav_int32_pcm_scaled_by_full_scale(registry):
    """SciPy's 32-bit PCM file: rate and counts from the RIFF chunks, parsed here."""
    file = DATA / "test-44100Hz-le-1ch-4bytes.wav"
    rate, bits, data = _wav_data_chunk(file)
    (info,) = scan_file(file, registry.signal_readers())[1]
    assert (info.rate_hz, info.n_samples, info.units) == (rate, 4410, None) == (44100, 4410, None)
    counts = np.frombuffer(data, dtype="<i4").astype(np.float64)
    expected = counts / 2.0 ** (bits - 1) * 50.0
    np.testing.assert_array_equal(_read(registry, file, full_scale_g="50")[0], expected)


def test_wav_unsigned_8bit_stereo_against_the_wave_module(registry):
    file = DATA / "test-8000Hz-le-2ch-1byteu.wav"
    with wave.open(str(file)) as handle:
        rate, frames = handle.getframerate(), handle.readframes(handle.getnframes())
    counts = np.frombuffer(frames, dtype=np.uint8).reshape(-1, 2).astype(np.float64)
    infos = scan_file(file, registry.signal_readers(), full_scale_g=2.0)[1]
    assert [(i.variable, i.rate_hz, i.units) for i in infos] == [
        ("ch1", rate, "g"),
        ("ch2", rate, "g"),
    ]
    expected = (counts[:, 1] - 128.0) / 128.0 * 2.0
    np.testing.assert_array_equal(_read(registry, file, "ch2", full_scale_g=2.0)[0], expected)


def test_wav_float_samples_are_taken_as_stored(registry):
    file = DATA / "test-44100Hz-2ch-32bit-float-le.wav"
    _, _, data = _wav_data_chunk(file)
    stored = np.frombuffer(data, dtype="<f4").reshape(-1, 2).astype(np.float64)
    np.testing.assert_array_equal(_read(registry, file, "ch1")[0], stored[:, 0])


def test_a_file_without_a_known_suffix_is_read_by_its_first_bytes(registry, tmp_path):
    copy = tmp_path / "recording.dat"
    copy.write_bytes((DATA / "raw1.tdms").read_bytes())
    assert reader_for(copy, registry.signal_readers()).name == "tdms"


def test_a_truncated_wav_is_refused_not_shortened(registry):
    cut = "truncated: the file holds 1,024 bytes, its RIFF header declares 17,708"
    with pytest.raises(DataFileError, match=cut):
        scan_file(DATA / "test-44100Hz-le-1ch-4bytes-early-eof.wav", registry.signal_readers())
