"""LVM files whose header does not describe their samples, and LabVIEW layouts main refused
(issue 41, items 1, 2, 7).

On main: a copy whose header kept a 51.2 kHz ``Delta_X`` over an X column stepping 5 ms was
read at 51.2 kHz (exit 0), or, with fewer rows than its ``Samples``, refused as "cut short";
a spectrum (``X_Dimension`` ``Frequency``) was read as a time signal in g; in LabVIEW's
``Multi`` layout a channel shorter than the others was listed at the others' length and
refused when read; a column-name row ending in a separator made a channel ``''`` that kept
``sdt dataset manifest`` from using the file; a ``Delta_X`` printed ``0.000977`` refused a
manifest rate of 1024 Hz. Files are real (``corpus/``, read with lvm_read alongside) or
written in LabVIEW's layout (``daq_files.py``).
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from sdt_plugins.readers.lvm_layout import printed_tolerance

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import read_signal, scan_file

from .daq_files import CORPUS, Channel, lvm_text

HEADER = "path,variable,sampling_rate_hz,units,condition,severity,recording_id,channel"


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def _values(n: int, seed: int = 0) -> np.ndarray:
    return np.round(np.random.default_rng(seed).normal(scale=0.3, size=n), 6)


def test_a_decimated_copy_of_a_real_recording_that_kept_its_header(sdt_main, tmp_path):
    """ARTS-Lab's 51.2 kHz Test_001.lvm with every 256th row kept under its own header: the X
    column steps 5 ms, Delta_X says 1.953125e-05 s, Samples 51,200 over 200 rows. Main called
    it "cut short"; the reason is named: the header does not describe the samples."""
    lines = (
        (CORPUS / "arts-lab-dataset5-Test_001.lvm")
        .read_text(encoding="utf-8")
        .splitlines(keepends=True)
    )
    start = next(i for i, line in enumerate(lines) if line.startswith("X_Value")) + 1
    copy = tmp_path / "decimated.lvm"
    copy.write_text("".join(lines[:start] + lines[start::256]), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(copy))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {copy}: channel 'Acceleration_0': its header's Delta_X is 1.953125e-05 s "
        f"(51200 Hz) but its X column steps 0.005 s (200 Hz) in segment 1 (row 2 is at 0.005 s, "
        f"Delta_X puts it at 1.95313e-05 s), and its Samples says 51,200 where the segment "
        f"holds 200 rows; the header does not describe these samples (a resampled or edited "
        f"copy that kept its header?); export the file again, or correct Delta_X"
    )


def test_a_header_rate_256_times_the_x_column_is_refused_not_read(sdt_main, tmp_path, readers):
    """Samples 1,024 (a first write) over 2,048 rows stepping 5 ms: main read it at 51.2 kHz."""
    x = np.arange(2048) * 0.005
    channel = Channel("acc", _values(2048), 1 / 51_200, x=x, samples=1024)
    file = tmp_path / "rec.lvm"
    file.write_text(lvm_text([[channel]], layout="One"), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    line = _one_error_line(err)
    assert "its header's Delta_X is 1.953125e-05 s (51200 Hz) but its X column steps 0.005 s " in (
        line
    )
    assert "and its Samples says 1,024 where the segment holds 2,048 rows" in line
    with pytest.raises(DataFileError, match="the header does not describe these samples"):
        read_signal(file, readers, "acc")
    # the same rows under a header at their own rate read, X column and all
    file.write_text(lvm_text([[Channel("acc", channel.values, 0.005)]], layout="One"))
    np.testing.assert_array_equal(read_signal(file, readers, "acc")[0], channel.values)


def test_x_values_printed_with_six_decimals_agree_with_their_delta_x(tmp_path, readers):
    """LabVIEW prints X with six decimals (0.000020 for 1.953125e-05 s, 2.4 % off per step):
    the check allows one unit of the sixth decimal, so a 51.2 kHz file written so reads."""
    x = np.round(np.arange(4096) / 51_200, 6)
    channel = Channel("acc", _values(4096), 1 / 51_200, x=x)
    file = tmp_path / "rec.lvm"
    file.write_text(lvm_text([[channel]]), encoding="utf-8")
    np.testing.assert_array_equal(read_signal(file, readers, "acc")[0], channel.values)


def test_an_lvm_spectrum_is_refused_naming_its_x_dimension(sdt_main, tmp_path):
    """A 0.015625 Hz-resolution spectrum saved by LabVIEW: main read it as a 64 Hz signal."""
    channel = Channel("acc", np.abs(_values(4097)), 0.015625, dimension="Frequency")
    file = tmp_path / "spectrum.lvm"
    file.write_text(lvm_text([[channel]], layout="One"), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: channel 'acc' is a spectrum: its X_Dimension is 'Frequency', not "
        f"'Time'; sdt reads time signals: save the time waveform"
    )


def test_multi_time_columns_with_a_channel_shorter_than_the_other(sdt_main, tmp_path, readers):
    """LabVIEW's Multi layout: 'acc' at 20 kHz (2,048 rows), 'acc 2' at 10 kHz (1,024 rows, its
    cells empty below them). Each reads as lvm_read reads its column, at its own rate; main
    listed 'acc 2' at 2,048 samples and refused it when read (a non-finite value)."""
    import lvm_read

    a, b = _values(2048), _values(1024, 1)
    file = tmp_path / "multi.lvm"
    file.write_text(lvm_text([[Channel("acc", a, 5e-5), Channel("acc 2", b, 1e-4)]]),
                    encoding="utf-8")  # fmt: skip
    code, out, err = sdt_main("dataset", "inspect", "--json", str(file))
    assert code == 0, err
    signals = {s["variable"]: s for s in json.loads(out)["signals"]}
    assert (signals["acc 2"]["n_samples"], signals["acc 2"]["rate_hz"]) == (1024, 10_000.0)
    assert (signals["acc"]["n_samples"], signals["acc"]["rate_hz"]) == (2048, 20_000.0)
    segment = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)[0]
    assert segment["Channel names"] == ["X_Value", "acc", "X_Value", "acc 2", "Comment"]
    np.testing.assert_array_equal(read_signal(file, readers, "acc")[0], segment["data"][:, 1])
    np.testing.assert_array_equal(read_signal(file, readers, "acc 2")[0], segment["data"][:1024, 3])
    assert np.isnan(segment["data"][1024:, 3]).all()


@pytest.mark.parametrize("layout", ["Multi", "One"])
def test_a_column_name_row_ending_in_a_separator_makes_no_channel(sdt_main, tmp_path, layout):
    """'X_Value\\tacc\\tX_Value\\tacc 2\\t': main made a channel '' with no rate, and
    `sdt dataset manifest` used none of the file ("holds no rate; give --rate-hz")."""
    text = lvm_text([[Channel("acc", _values(2048), 5e-5), Channel("acc 2", _values(2048, 1),
                                                                  5e-5)]], layout)  # fmt: skip
    folder = tmp_path / "tree" / "healthy"
    folder.mkdir(parents=True)
    (folder / "r1.lvm").write_text(text.replace("\tComment\n", "\t\n"), encoding="utf-8")
    out_csv = tmp_path / "m.csv"
    code, out, err = sdt_main("dataset", "manifest", str(tmp_path / "tree"), "--pattern",
                              "{condition}/{run}.lvm", "--out", str(out_csv))  # fmt: skip
    assert code == 0, err
    assert "wrote" in out and "2 rows from 1 files" in out and "0 not used" in out
    with open(out_csv, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["variable"], r["sampling_rate_hz"]) for r in rows] == [
        ("acc", "20000.0"),
        ("acc 2", "20000.0"),
    ]


def test_a_delta_x_printed_with_six_decimals_takes_the_rate_it_stands_for(sdt_main, tmp_path):
    """lvm_read's long_single_header_multi_ch.lvm prints Delta_X 0.000977 (1/1024 s to six
    decimals): 1023.54 Hz within half a unit of its last digit, 0.051 %. A manifest rate of
    1024 Hz (0.045 % away) is taken, as main did not; 1020 Hz (0.35 %) is still refused."""
    file = tmp_path / "long.lvm"
    file.write_bytes((CORPUS / "lvm_read-long_single_header_multi_ch.lvm").read_bytes())
    manifest = tmp_path / "m.csv"
    for rate, code_expected in ((1024, 0), (1020, 2)):
        manifest.write_text(f"{HEADER}\nlong.lvm,F,{rate},g,healthy,,r1,ch1\n", encoding="utf-8")
        code, _, err = sdt_main("dataset", "inspect", str(manifest))
        assert code == code_expected, err
    assert "runs at 1023.54 Hz by its Delta_X, the manifest says 1020 Hz" in err


@pytest.mark.parametrize(
    ("text", "step", "half"),
    [
        ("0.000977", 0.000977, 0.5e-6),  # six decimals
        ("0,000250", 0.000250, 0.5e-6),  # a comma decimal separator
        ("1.953125E-5", 1.953125e-5, 0.5e-11),  # 7 significant digits: under the 1e-6 floor
        ("5.00E-4", 5e-4, 0.5e-6),
    ],
)
def test_the_tolerance_of_a_printed_delta_x_is_half_its_last_digit(text, step, half):
    """A rate 1/step is within r / (1 - r) of the true one, r = half / step, and never held to
    less than the 1e-6 of a header rate."""
    r = half / step
    assert printed_tolerance(text, step) == pytest.approx(max(1e-6, r / (1 - r)), rel=1e-12)


def test_a_channel_without_units_says_it_is_read_in_g(sdt_main, tmp_path):
    file = tmp_path / "rec.lvm"
    file.write_text(lvm_text([[Channel("acc", _values(2048), 5e-5, units="")]]), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    assert f"note: {file}: signal 'acc' states no units (its Y_Unit_Label is empty): read in" in (
        " ".join(err.split())
    )


def test_two_columns_of_one_name_are_refused_not_one_dropped(tmp_path, readers):
    """Main kept the first column of a repeated name and dropped the other without a word."""
    file = tmp_path / "rec.lvm"
    same_name = [Channel("acc", _values(64), 5e-5), Channel("acc", _values(64, 1), 5e-5)]
    file.write_text(lvm_text([same_name]), encoding="utf-8")
    with pytest.raises(DataFileError, match="2 columns are named 'acc'; rename them"):
        read_signal(Path(file), readers, "acc")


def test_a_column_name_row_without_x_value_is_named(sdt_main, tmp_path):
    """ARTS-Lab's Dataset-7 files name their columns ',time,excitation_vibration,...' (no
    'X_Value', which lvm_read looks for): main said `not a readable LVM file (lvm_read: 'data')`."""
    text = lvm_text([[Channel("acc", _values(64), 5e-5)]], layout="One")
    file = tmp_path / "rec.lvm"
    file.write_text(text.replace("X_Value\tacc\tComment", "\tacc\tComment"), encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert _one_error_line(err) == (
        f"error: {file}: no column-name row: LabVIEW begins each segment's data with a row whose "
        f"first cell is 'X_Value', and lvm_read finds none (a file written by another program, "
        f"or edited); add that row, or export the file again from LabVIEW"
    )


def test_a_file_rewritten_with_the_same_size_and_time_is_parsed_again(tmp_path, readers):
    """The parse kept for the next call is keyed by the file's content, not its name,
    size or time: a corrected file is read as it now stands."""
    import os

    file = tmp_path / "r.lvm"
    rate = 1000.0
    values, sizes = {}, set()
    for k, level in enumerate((0.25, 0.5)):
        tone = level * np.sin(2 * np.pi * 50 * np.arange(200) / rate)
        file.write_text(lvm_text([[Channel("acc", tone, 1 / rate)]]), encoding="utf-8")
        os.utime(file, ns=(1_700_000_000_000_000_000, 1_700_000_000_000_000_000))
        sizes.add(file.stat().st_size)
        values[k] = read_signal(file, readers, "acc")
        np.testing.assert_allclose(values[k][0], tone, atol=1e-6)  # LabVIEW's 6 decimals
    assert len(sizes) == 1  # the same size and time: only the content tells them apart


def test_a_campaign_scanned_then_read_parses_each_file_once(tmp_path, readers, monkeypatch):
    """A benchmark probes every file of a campaign before it reads the first. Each parse is
    kept (by memory, not by a count of files), so each file is parsed once, and each read
    equals the values written (LabVIEW's 6 decimals)."""
    import lvm_read

    parses: list[str] = []
    real_read = lvm_read.read

    def counting_read(filename, *args, **kwargs):
        parses.append(Path(filename).name)
        return real_read(filename, *args, **kwargs)

    monkeypatch.setattr(lvm_read, "read", counting_read)
    rate, tones = 1000.0, {}
    for k in range(5):  # 5 files: more than the 2 a count-bounded cache kept
        tones[k] = (0.1 + 0.05 * k) * np.sin(2 * np.pi * 50 * np.arange(300) / rate)
        text = lvm_text([[Channel("acc", tones[k], 1 / rate)]])
        (tmp_path / f"f{k}.lvm").write_text(text, encoding="utf-8")
    files = [tmp_path / f"f{k}.lvm" for k in range(5)]
    for file in files:
        assert [s.variable for s in scan_file(file, readers)[1]] == ["acc"]
    for k, file in enumerate(files):
        np.testing.assert_allclose(read_signal(file, readers, "acc")[0], tones[k], atol=1e-6)
    assert sorted(parses) == [f"f{k}.lvm" for k in range(5)]
