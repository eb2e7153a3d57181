"""Bad DAQ files and manifests: one ``error:`` line naming the file and the value, exit 2."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

DATA = Path(__file__).parents[1] / "data" / "readers"
HEADER = "path,variable,sampling_rate_hz,units,condition,severity,recording_id,channel"


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert "Traceback" not in err
    return lines[0]


def _tdms(file: Path, rate: float = 25_600.0, units: str = "g") -> Path:
    from nptdms import ChannelObject, TdmsWriter

    props = {"wf_increment": 1 / rate, "unit_string": units}
    with TdmsWriter(file) as writer:
        writer.write_segment([ChannelObject("acc", "ch1", np.zeros(4096), properties=props)])
    return file


def test_a_truncated_tdms_file(sdt_main, tmp_path):
    whole = _tdms(tmp_path / "whole.tdms").read_bytes()
    cut = tmp_path / "cut.tdms"
    cut.write_bytes(whole[:-1000])
    code, _, err = sdt_main("dataset", "inspect", str(cut))
    assert code == 2
    assert "cut.tdms: truncated: its last segment holds less data" in _one_error_line(err)


@pytest.mark.parametrize("name", ["binary8byte.uff", "Sample_UFF58_ascii.uff"])
def test_a_truncated_uff_file(sdt_main, tmp_path, name):
    data = (DATA / name).read_bytes()
    cut = tmp_path / name
    cut.write_bytes(data[: len(data) // 2])
    code, _, err = sdt_main("dataset", "inspect", str(cut))
    assert code == 2
    assert f"{name}: truncated: the file does not end with a dataset's closing '-1'" in (
        _one_error_line(err)
    )


def test_a_uff_file_without_dataset_58(sdt_main):
    code, _, err = sdt_main("dataset", "inspect", str(DATA / "uff55_sample_test_record10.uff"))
    assert code == 2
    assert "holds no dataset 58 (time history); its datasets are 55" in _one_error_line(err)


def test_an_integer_wav_without_full_scale(sdt_main, tmp_path):
    shutil.copy(DATA / "test-44100Hz-le-1ch-4bytes.wav", tmp_path / "rec.wav")
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"{HEADER}\nrec.wav,,,,healthy,,r1,ch1\n", encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 2
    line = _one_error_line(err)
    assert "rec.wav: integer PCM (32-bit) samples are counts, not g" in line
    assert "manifest column 'full_scale_g'" in line
    manifest.write_text(f"{HEADER},full_scale_g\nrec.wav,,,,healthy,,r1,ch1,50\n", encoding="utf-8")
    code, out, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 0, err
    assert "44100" in out  # the rate came from the header


def test_a_manifest_rate_that_contradicts_the_file(sdt_main, tmp_path):
    _tdms(tmp_path / "rec.tdms")
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"{HEADER}\nrec.tdms,,20000,g,healthy,,r1,ch1\n", encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 2
    line = _one_error_line(err)
    assert "runs at 25600 Hz by its wf_increment, the manifest says 20000 Hz" in line
    assert "m.csv line 2" in line


def test_manifest_units_that_contradict_the_file_and_a_file_in_volts(sdt_main, tmp_path):
    _tdms(tmp_path / "rec.tdms", units="m/s^2")
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"{HEADER}\nrec.tdms,,,g,healthy,,r1,ch1\n", encoding="utf-8")
    code, _, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 2
    assert "gives its units as 'm/s^2', the manifest says units = g" in _one_error_line(err)
    _tdms(tmp_path / "rec.tdms", units="Volts")
    code, _, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 2
    assert "gives its units as 'Volts', not an acceleration" in _one_error_line(err)


def test_empty_rate_and_units_are_taken_from_the_file(registry, tmp_path):
    from sdt_framework.data import open_dataset

    _tdms(tmp_path / "rec.tdms", rate=51_200.0, units="m/s^2")
    manifest = tmp_path / "m.csv"
    manifest.write_text(f"{HEADER}\nrec.tdms,,,,healthy,,r1,ch1\n", encoding="utf-8")
    (recording,) = open_dataset(registry, str(manifest)).recordings()
    assert (recording.sampling_rate_hz, recording.units) == (51_200.0, "m/s^2")


def test_a_template_that_matches_nothing(sdt_main, tmp_path):
    tree = tmp_path / "tree" / "pump" / "healthy -" / "r1"
    tree.mkdir(parents=True)
    _tdms(tree / "ch1.tdms")
    code, _, err = sdt_main("dataset", "manifest", str(tmp_path / "tree"), "--pattern",
                            "{machine}/{condition} {severity}/{run}/{channel}.uff", "--out",
                            str(tmp_path / "m.csv"))  # fmt: skip
    assert code == 2
    line = _one_error_line(err)
    assert "matches none of the 1 files under" in line
    assert "'ch1.tdms' does not match" in line
    assert not (tmp_path / "m.csv").exists()


def test_a_file_of_no_recognised_format_names_those_that_are(sdt_main, tmp_path):
    odd = tmp_path / "run.xyz"
    odd.write_bytes(b"\x00\x01binary")
    code, _, err = sdt_main("dataset", "inspect", str(odd))
    assert code == 2
    line = _one_error_line(err)
    assert "run.xyz: format not recognised (suffix '.xyz'); sdt reads CSV (.csv)" in line
    for label in ("TDMS (.tdms)", "UFF58 (.uff, .unv, .uf)", "WAV (.wav)", "LabVIEW LVM (.lvm)",
                  "MATLAB v7.3 (.mat)", "enDAQ IDE (.ide)"):  # fmt: skip
        assert label in line


def test_manifest_building_names_what_a_file_lacks(sdt_main, tmp_path):
    """An integer WAV without --full-scale-g and an NPY without --rate-hz are not rows."""
    tree = tmp_path / "tree" / "bench" / "healthy" / "r1"
    tree.mkdir(parents=True)
    shutil.copy(DATA / "test-44100Hz-le-1ch-4bytes.wav", tree / "ch1.wav")
    np.save(tree / "ch2.npy", np.zeros(64))
    out = tmp_path / "m.csv"
    args = ("dataset", "manifest", str(tmp_path / "tree"), "--pattern",
            "{machine}/{condition}/{run}/{channel}", "--out", str(out))  # fmt: skip
    code, _, err = sdt_main(*args)
    assert code == 2
    line = _one_error_line(err)
    assert "matches 2 of the 2 files under" in line and "none of them could be read" in line
    assert "ch1.wav: integer PCM (32-bit) samples are counts" in line
    code, printed, err = sdt_main(*args, "--full-scale-g", "50")
    assert code == 0
    assert "not used: bench/healthy/r1/ch2.npy: a NPY file holds no rate; give --rate-hz" in err
    assert "1 rows from 1 files (1 recordings); 1 not used" in printed
    assert (
        out.read_text(encoding="utf-8")
        .splitlines()[1]
        .endswith(",44100.0,healthy,,r1,ch1.wav,bench,g,ch1,50.0")
    )
