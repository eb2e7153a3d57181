"""WAV as recorders write it (issue 41, item 6): 24-bit and 20-bit PCM in 3-byte containers,
big-endian RIFX, RF64, and files with extra chunks (PEAK, Broadcast WAV ``bext``, ``iXML``).

On main every one of these was refused: scipy.io.wavfile's memory map cannot hold a 3-byte
sample ("mmap=True not compatible with 3-byte container size"), the reader turned scipy's
warning about an unknown chunk into an error, and RIFX was not recognised as WAV. Values are
checked against the file's bytes, parsed here, and against scipy.io.wavfile (the corpus test).
"""

from __future__ import annotations

import tracemalloc
from pathlib import Path

import numpy as np
import pytest
import soundfile

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import read_signal, scan_file

DATA = Path(__file__).parents[1] / "data" / "readers"
CORPUS = DATA / "corpus"


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def _counts_24bit(raw: bytes, channels: int) -> np.ndarray:
    """(frames, channels) signed counts of little-endian 3-byte samples, by hand."""
    b = np.frombuffer(raw, dtype=np.uint8).reshape(-1, 3).astype(np.int64)
    value = b[:, 0] | (b[:, 1] << 8) | (b[:, 2] << 16)
    return np.where(value >= 1 << 23, value - (1 << 24), value).reshape(-1, channels)


def test_a_24_bit_wav_written_by_libsndfile_reads_in_g(tmp_path, readers):
    rng = np.random.default_rng(4)
    counts = rng.integers(-(2**23), 2**23, size=(4096, 3), dtype=np.int32)
    file = tmp_path / "rec.wav"
    soundfile.write(file, counts << 8, 25_600, subtype="PCM_24")  # left-justified in int32
    raw = file.read_bytes()
    start = raw.index(b"data") + 8
    on_disk = _counts_24bit(raw[start : start + 4096 * 9], 3)
    np.testing.assert_array_equal(on_disk, counts)  # the writer stored the counts given
    _, infos = scan_file(file, readers, full_scale_g=8.0)
    assert [(i.variable, i.label, i.rate_hz, i.units) for i in infos] == [
        (f"ch{k}", "PCM 24-bit", 25_600.0, "g") for k in (1, 2, 3)
    ]
    np.testing.assert_array_equal(
        read_signal(file, readers, "ch3", full_scale_g=8.0)[0], on_disk[:, 2] / 2.0**23 * 8.0
    )


def test_a_field_recorders_broadcast_wav_is_listed_with_its_rate(sdt_main):
    """A Sound Devices recorder's file (wavinfo's test data): bext and iXML chunks."""
    file = CORPUS / "wavinfo-sounddevices-A101_3.WAV"
    code, out, err = sdt_main("dataset", "inspect", str(file), "--json")
    assert code == 0, err
    assert '"label": "PCM 24-bit"' in out and '"rate_hz": 48000.0' in out
    assert out.count('"n_samples": 48044') == 2


@pytest.mark.parametrize(
    ("name", "twin"),
    [
        ("test-8000Hz-be-3ch-5S-24bit.wav", CORPUS / "test-8000Hz-le-3ch-5S-24bit.wav"),
        ("test-44100Hz-be-1ch-4bytes.wav", DATA / "test-44100Hz-le-1ch-4bytes.wav"),
    ],
)
def test_big_endian_rifx_is_read_as_its_little_endian_riff_twin(name, twin, readers):
    """scipy's RIFX files hold the samples of their RIFF twins, byte-swapped."""
    _, infos = scan_file(CORPUS / name, readers, full_scale_g=1.0)
    for info in infos:
        np.testing.assert_array_equal(
            read_signal(CORPUS / name, readers, info.variable, full_scale_g=1.0),
            read_signal(twin, readers, info.variable, full_scale_g=1.0),
        )


@pytest.mark.parametrize(
    ("name", "says"),
    [
        (
            "test-8000Hz-le-3ch-5S-64bit.wav",
            "not a readable WAV file (libsndfile: File contains data in an unimplemented "
            "format.); sdt reads integer PCM of 8 to 32 bits and 32/64-bit float (RIFF, RIFX "
            "or RF64)",
        ),
        (
            "test-8000Hz-le-1ch-1byte-ulaw.wav",
            "its samples are U-Law (ULAW), a compressed or unusual encoding, not the recorded "
            "signal; sdt reads integer PCM (8 to 32 bits) and float WAV: export the recording "
            "again as 24-bit PCM or 32-bit float",
        ),
    ],
)
def test_an_encoding_sdt_does_not_read_is_one_line(sdt_main, name, says):
    file = DATA / name
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == f"error: {file}: {says}"


def test_reading_one_channel_holds_that_channel_and_one_block(tmp_path, readers):
    """8 channels of 2**19 24-bit frames (12 MB of samples): reading one channel allocates
    its float64 samples (4 MB) and one block, not the file's samples (scipy: 12 MB read,
    then a 16 MB int32 copy); listing the channels reads none."""
    frames = 2**19
    file = tmp_path / "long.wav"
    column = np.arange(frames, dtype=np.int32) - frames // 2
    soundfile.write(file, np.repeat(column[:, None] << 8, 8, axis=1), 51_200, subtype="PCM_24")
    tracemalloc.start()
    try:
        scan_file(file, readers, full_scale_g=1.0)
        listed = tracemalloc.get_traced_memory()[1]
        tracemalloc.reset_peak()
        values = read_signal(file, readers, "ch5", full_scale_g=1.0)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    np.testing.assert_array_equal(values[0], column / 2.0**23)
    assert listed < 200_000
    assert peak < 8 * frames + 1.2 * frames + 8 * 4 * 131_072 + 1_000_000  # ~10 MB, not 28+


def test_a_file_shorter_than_its_riff_header_declares_is_refused(tmp_path, readers):
    """libsndfile would read what is left; the RIFF size says the file was cut."""
    whole = (CORPUS / "wavinfo-protools-umid.wav").read_bytes()
    cut = tmp_path / "cut.wav"
    cut.write_bytes(whole[:100_000])
    with pytest.raises(DataFileError, match="truncated: the file holds 100,000 bytes"):
        scan_file(cut, readers, full_scale_g=1.0)
