"""Files that main read wrong with exit 0 are refused, naming the segment or field (issue 39,
item 7).

On main: a TDMS channel whose ``wf_increment`` or ``unit_string`` changes between segments
had the last value applied to every sample (npTDMS merges properties); an LVM whose segments
have different ``Delta_X`` was read at the first segment's rate; a truncated LVM was read
short, its last number cut (``0.330112`` read as ``0.330``); a MATLAB v5 logical array was
read as 0/1 g and benchmarked. The TDMS files are written with npTDMS's TdmsWriter, the MAT
file with scipy.io.savemat, the LVM files as LabVIEW writes them (``labview.py``).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import scipy.io

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import read_signal

from ..helpers import six_recordings
from .labview import lvm, segment


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def _tdms(file: Path, segments: list[dict]) -> Path:
    """One channel ``acc/ch1`` of 4096 values per segment, each with ``segments[i]`` as its
    properties (npTDMS writes a segment's properties with its data)."""
    from nptdms import ChannelObject, TdmsWriter

    with TdmsWriter(file) as writer:
        for i, props in enumerate(segments):
            data = np.full(4096, float(i + 1))
            writer.write_segment([ChannelObject("acc", "ch1", data, properties=props)])
    return file


G = {"wf_increment": 1 / 25_600, "unit_string": "g"}


@pytest.mark.parametrize(
    ("second", "words"),
    [
        ({"wf_increment": 1 / 12_800}, "changes its wf_increment from 3.90625e-05 (segment 1) "
         "to 7.8125e-05 at segment 2, after 4,096 values"),
        ({"unit_string": "m/s^2"}, "changes its unit_string from 'g' (segment 1) to 'm/s^2' at "
         "segment 2, after 4,096 values"),
    ],
)  # fmt: skip
def test_a_tdms_channel_whose_rate_or_units_change_between_segments(
    sdt_main, tmp_path, second, words, readers
):
    file = _tdms(tmp_path / "rec.tdms", [G, second])
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: channel 'acc/ch1' {words}; npTDMS applies the last value to every "
        f"sample, so the channel is not one record; split the file at that segment, or write "
        f"one rate, unit and scale per channel"
    )
    with pytest.raises(DataFileError, match=re.escape(words)):
        read_signal(file, readers, "acc/ch1")


def test_a_tdms_channel_given_the_same_properties_in_every_segment_reads_whole(tmp_path, readers):
    """LabVIEW writes a channel's properties again with each segment: no change, no refusal;
    the segments' values follow each other in order."""
    file = _tdms(tmp_path / "rec.tdms", [G, G, dict(G)])
    data = read_signal(file, readers, "acc/ch1")
    np.testing.assert_array_equal(data[0], np.repeat([1.0, 2.0, 3.0], 4096))


def _rows(n: int, seed: int = 0) -> np.ndarray:
    return np.round(np.random.default_rng(seed).normal(scale=0.3, size=(n, 1)), 6)


def test_lvm_segments_at_different_delta_x_are_refused_naming_the_segment(sdt_main, tmp_path):
    file = tmp_path / "rec.lvm"
    first, second = segment(["acc"], _rows(2048), 1 / 25_600), segment(["acc"], _rows(2048, 1),
                                                                       1 / 12_800)  # fmt: skip
    file.write_text(lvm([first, second]), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: channel 'acc' has Delta_X 3.90625e-05 s in segment 1 and 7.8125e-05 s "
        f"in segment 2: its segments, read as acquisitions, are not at one rate; split the file "
        f"at segment 2"
    )


def test_lvm_segments_at_one_delta_x_are_its_acquisitions(tmp_path, readers):
    file = tmp_path / "rec.lvm"
    rows = [_rows(2048, seed) for seed in range(3)]
    file.write_text(lvm([segment(["acc"], r, 1 / 25_600) for r in rows]), encoding="utf-8")
    np.testing.assert_array_equal(
        read_signal(file, readers, "acc"), np.stack([r[:, 0] for r in rows])
    )


def test_an_lvm_cut_inside_its_last_value_is_refused(sdt_main, tmp_path):
    text = lvm([segment(["acc"], _rows(2048), 1 / 25_600)])
    last = text.rstrip("\n").rsplit("\t", 1)[1]  # '0.330112'-like: six decimals
    assert len(last.lstrip("-")) == 8
    file = tmp_path / "cut.lvm"
    file.write_text(text[: len(text) - 5], encoding="utf-8")  # the line break and 4 digits
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: truncated: its last line ends without a line break, in "
        f"{last[:-4]!r}; LabVIEW ends every line, so the file was cut short and its last value "
        f"may be cut too; copy it again"
    )


def test_an_lvm_cut_at_a_line_break_is_refused_by_its_samples_count(sdt_main, tmp_path):
    text = lvm([segment(["acc"], _rows(2048), 1 / 25_600)])
    file = tmp_path / "cut.lvm"
    file.write_text("".join(text.splitlines(keepends=True)[:-100]), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: truncated: segment 1 holds 1,948 rows, its header's Samples says "
        f"2,048; the file was cut short; copy it again"
    )


def test_a_matlab_logical_array_stops_the_benchmark(sdt_main, tmp_path):
    """On main it was read as 0/1 g and benchmarked (exit 0)."""
    manifest = six_recordings(tmp_path)
    flags = np.load(tmp_path / "healthy0.npy") > 0
    scipy.io.savemat(tmp_path / "healthy0.mat", {"x": flags})
    assert scipy.io.whosmat(tmp_path / "healthy0.mat") == [("x", (1, 40_000), "logical")]
    text = manifest.read_text(encoding="utf-8").replace("healthy0.npy", "healthy0.mat")
    manifest.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    code, _, err = sdt_main("benchmark", "--data", str(manifest), "--quick", "--out", str(out))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {tmp_path / 'healthy0.mat'}: variable 'x' is a MATLAB logical array "
        f"(true/false), not samples; save the signal as double (in g) (manifest {manifest} "
        f"line 2)"
    )
    assert not out.exists()
