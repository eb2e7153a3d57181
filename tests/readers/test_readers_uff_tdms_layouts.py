"""UFF and TDMS layouts main read wrong or refused (issue 41, items 2, 8, 9, 14).

On main: HBM catman's closing ``-1``, padded with spaces to 80 columns, was taken for a file
cut short; a PSD beside a file's time histories (its abscissa increment 0) made
``sdt dataset manifest`` leave out the whole file; a TDMS group named with a date
(``07/09/2012 ...``) listed its channels and failed every read; a TDMS channel whose x axis is
in Hz (a spectrum) was read as a time signal; a channel with no ``unit_string`` was read in g
without a word. Files are real (``corpus/``), written by pyuff or npTDMS, or in catman's
layout (``daq_files.py``).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import read_signal, scan_file

from .daq_files import CATMAN, CORPUS, PSD, catman_uff


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def test_catman_file_reads_and_a_cut_one_is_still_refused(sdt_main, tmp_path):
    """The real catman file reads (main: "truncated"); the same file cut before its closing
    -1, or inside its padding's first columns, is refused as cut short."""
    code, out, err = sdt_main("dataset", "inspect", str(CATMAN))
    assert code == 0, err
    assert "samples: 13  rate Hz: 20000 (abscissa_inc)  units: m/s²" in out
    whole = CATMAN.read_bytes()
    assert whole.endswith(b"    -1" + b" " * 74 + b"\n")
    for cut in (whole[:-81], whole[:-78]):  # the -1 line gone; '    -' left of it
        file = tmp_path / "cut.uff"
        file.write_bytes(cut)
        code, _, err = sdt_main("dataset", "inspect", str(file))
        assert code == 2
        assert "truncated: the file does not end with a dataset's closing '-1' line" in (
            _one_error_line(err)
        )


def _psd(label: str | None) -> dict:
    """The PSD of pyuff's real VibControl export (uneven abscissa, increment 0), its ordinate
    units label replaced by ``label`` where one is given."""
    import pyuff

    psd = pyuff.UFF(str(PSD)).read_sets(0)
    return psd if label is None else {**psd, "ordinate_axis_units_lab": label}


@pytest.mark.parametrize(
    ("label", "note"),
    [
        ("NONE", "2 signals skipped: not readable as they stand, in 2 files (e.g. '3' in "
         "healthy/r1.uff: dataset 58 #3 is a power spectral density (function type 9), not a "
         "time response (type 1); export the time history)"),
        (None, "2 signals skipped: not an acceleration unit ('g\ufffd/Hz': 2), in 2 files"),
    ],
    ids=["no-units", "as-exported"],
)  # fmt: skip
def test_a_psd_beside_catman_time_histories_leaves_them_readable(
    sdt_main, tmp_path, label, note, readers
):
    """Two catman time histories, then a PSD appended by pyuff: the manifest holds both time
    histories and names the PSD it left out; each reads as pyuff reads it. On main a PSD with
    no units label (its increment 0, no rate) left the whole file out ("a UFF58 file holds no
    rate; give --rate-hz"); one labelled g²/Hz was left out for its unit, as now."""
    import pyuff

    rng = np.random.default_rng(0)
    histories = {name: rng.normal(scale=3.0, size=4096) for name in ("1x", "2x")}
    for run in ("r1", "r2"):
        folder = tmp_path / "tree" / "healthy"
        folder.mkdir(parents=True, exist_ok=True)
        file = folder / f"{run}.uff"
        file.write_text(catman_uff(histories, 20_000.0), encoding="utf-8")
        pyuff.UFF(str(file)).write_sets(_psd(label), mode="add")
    code, out, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    assert "listed, not read" in err and "dataset 58 #3 is a power spectral density" in err
    manifest = tmp_path / "m.csv"
    code, out, err = sdt_main("dataset", "manifest", str(tmp_path / "tree"), "--pattern",
                              "{condition}/{run}.uff", "--out", str(manifest))  # fmt: skip
    assert code == 0, err
    assert "4 rows from 2 files (4 recordings); 0 not used" in out
    assert f"note: {note}" in " ".join(err.split())
    with open(manifest, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert {(r["variable"], r["units"], r["sampling_rate_hz"]) for r in rows} == {
        ("1", "m/s^2", "20000.0"),
        ("2", "m/s^2", "20000.0"),
    }
    sets = pyuff.UFF(str(file)).read_sets([0, 1])
    for number, dataset in enumerate(sets, start=1):
        np.testing.assert_array_equal(read_signal(file, readers, str(number))[0], dataset["data"])


def _tdms(file: Path, channels: list[tuple[str, str, np.ndarray, dict]]) -> Path:
    from nptdms import ChannelObject, TdmsWriter

    with TdmsWriter(file) as writer:
        writer.write_segment([ChannelObject(g, c, d, properties=p) for g, c, d, p in channels])
    return file


G = {"wf_increment": 1 / 25_600, "unit_string": "g"}


def test_group_and_channel_names_holding_slashes_read_their_own_channel(tmp_path, readers):
    """A logger's group '2024/07/01 10:00' and a channel 'acc/x': each read is npTDMS's."""
    from nptdms import TdmsFile

    a, b = np.arange(4096.0), -np.arange(4096.0)
    file = _tdms(tmp_path / "log.tdms", [("2024/07/01 10:00", "acc/x", a, G),
                                         ("2024/07/01 10:00", "acc y", b, G)])  # fmt: skip
    np.testing.assert_array_equal(read_signal(file, readers, "2024/07/01 10:00/acc/x")[0], a)
    np.testing.assert_array_equal(read_signal(file, readers, "2024/07/01 10:00/acc y")[0],
                                  TdmsFile.read(file)["2024/07/01 10:00"]["acc y"][:])  # fmt: skip


def test_two_channels_joined_to_one_name_are_refused_naming_it(tmp_path, readers):
    file = _tdms(tmp_path / "log.tdms", [("a/b", "c", np.zeros(64), G),
                                         ("a", "b/c", np.ones(64), G)])  # fmt: skip
    with pytest.raises(DataFileError, match=r"2 channels are named 'a/b/c' \(group and channel "):
        read_signal(file, readers, "a/b/c")


@pytest.mark.parametrize(
    ("props", "words"),
    [
        ({"wf_xunit_string": "Hz", "wf_xname": "Frequency"},
         "is a spectrum, not a time signal: its wf_xunit_string is 'Hz'"),
        ({"wf_xname": "Frequency"}, "is a spectrum, not a time signal: its wf_xname is "
         "'Frequency'"),
        ({"wf_xunit_string": "ms"}, "its wf_xunit_string is 'ms', not seconds"),
    ],
)  # fmt: skip
def test_a_tdms_channel_whose_x_axis_is_not_seconds_is_refused(sdt_main, tmp_path, props, words):
    """A spectrum at 0.015625 Hz resolution: main read it as a 64 Hz signal in g."""
    spectrum = np.abs(np.random.default_rng(0).normal(size=4097))
    props = {"wf_increment": 0.015625, "wf_start_offset": 0.0, "unit_string": "g", **props}
    file = _tdms(tmp_path / "fft.tdms", [("FFT", "acc", spectrum, props)])
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert f"error: {file}: channel 'FFT/acc'" in _one_error_line(err)
    assert words in _one_error_line(err)


def test_a_time_waveform_written_by_labview_reads(registry):
    """npTDMS's big_endian.tdms (LabVIEW): wf_xname 'Time', wf_xunit_string 's'."""
    file = CORPUS / "npTDMS-big_endian.tdms"
    _, infos = scan_file(file, registry.signal_readers())
    assert [i.fault for i in infos] == [None, None]


def test_a_channel_without_unit_string_is_named_in_inspect_and_manifest(
    sdt_main, tmp_path, readers
):
    """LabVIEW's Digital_Input.tdms states no units: inspect names the channels it reads in g,
    `sdt dataset manifest` counts them, and the signals say so (units_stated)."""
    file = CORPUS / "npTDMS-Digital_Input.tdms"
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    said = " ".join(err.split())
    assert (
        f"note: {file}: signals '07/09/2012 06:58:23 PM - Digital Input - All "
        f"Data/Dev1_port3_line7 - line 0', '07/09/2012 06:58:23 PM - Digital Input - Decimated "
        f"Data_Level1/Dev1_port3_line7 - line 0' state no units (its unit_string is empty)"
    ) in said
    folder = tmp_path / "tree" / "healthy"
    folder.mkdir(parents=True)
    _tdms(folder / "r1.tdms", [("acc", "x", np.zeros(4096), {"wf_increment": 1 / 25_600}),
                               ("acc", "y", np.zeros(4096), G)])  # fmt: skip
    tree, manifest = str(tmp_path / "tree"), str(tmp_path / "m.csv")
    code, _, err = sdt_main("dataset", "manifest", tree, "--pattern", "{condition}/{run}.tdms",
                            "--out", manifest)  # fmt: skip
    assert code == 0, err
    assert (
        "note: 1 signal states no units (their unit_string is empty), in 1 file (e.g. 'acc/x' "
        "in healthy/r1.tdms): written with units empty, which the manifest reads as g"
    ) in " ".join(err.split())
    infos = {i.variable: i for i in scan_file(folder / "r1.tdms", readers)[1]}
    assert (infos["acc/x"].units_stated, infos["acc/y"].units_stated) == (False, True)
