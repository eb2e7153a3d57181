"""What ``sdt dataset inspect`` and ``sdt dataset manifest`` say of a signal file (issue 39,
weak items).

On main: a header-less signal CSV given to ``inspect`` was read as a manifest ("unknown
column(s) '-0.057630'"); a 100,000-character channel name printed a 100 kB line; lvm_read's
``ast`` errors leaked (``<ast.Name object at 0x7f...>``); several NI channels of one file under
one ``{channel}`` became one channel's acquisitions without a word, and a MATLAB N x 3 matrix
three acquisitions of one signal without a note.
"""

from __future__ import annotations

import numpy as np
import scipy.io

from .labview import lvm, segment


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def test_a_header_less_signal_csv_is_inspected_as_a_signal(sdt_main, tmp_path):
    file = tmp_path / "acc.csv"
    np.savetxt(file, np.random.default_rng(0).normal(size=(3000, 1)), fmt="%.6f", delimiter=",")
    assert file.read_text().splitlines()[0].startswith(("0.", "-0."))  # numbers from line 1
    code, out, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    shown = "".join(out.split())  # the title and table may fold over lines
    assert f"{file}:CSV,1signal" in shown
    assert "│-│-│1│3000│-│-│-│" in shown  # one acquisition of 3000 samples, no rate


def test_a_csv_naming_manifest_columns_is_still_a_manifest(sdt_main, tmp_path):
    np.save(tmp_path / "a.npy", np.zeros(40_000))
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
        "a.npy,20000,healthy,,r1,ch1\n",
        encoding="utf-8",
    )
    code, out, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 0, err
    assert "manifest: 1 recordings in 1 runs" in out


def test_a_100000_character_channel_name_is_cut_in_the_middle(sdt_main, tmp_path):
    from nptdms import ChannelObject, TdmsWriter

    name = "a" + "x" * 99_998 + "z"
    file = tmp_path / "long.tdms"
    props = {"wf_increment": 1 / 25_600, "unit_string": "g"}
    with TdmsWriter(file) as writer:
        writer.write_segment([ChannelObject("g", name, np.zeros(4096), properties=props)])
    code, out, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    assert len(out) < 3000
    shown = "".join(out.split())  # the table may fold the cell over lines
    assert f"g/a{'x' * 57}…{'x' * 59}z(100,002characters)" in shown


def test_100000_character_labels_of_a_manifest_are_cut_in_inspect(sdt_main, tmp_path):
    np.save(tmp_path / "a.npy", np.zeros(40_000))
    condition, channel = "h" * 100_000, "c" * 100_000
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
        f"a.npy,20000,{condition},,r1,{channel}\n",
        encoding="utf-8",
    )
    code, out, err = sdt_main("dataset", "inspect", str(manifest))
    assert code == 0, err
    assert len(out) + len(err) < 5000
    assert f"{'h' * 60}…{'h' * 60} (100,000 characters)" in out


def test_an_lvm_header_value_that_is_not_a_number_is_named_with_its_line(sdt_main, tmp_path):
    rows = np.round(np.random.default_rng(0).normal(size=(100, 1)), 6)
    text = lvm([segment(["acc"], rows, 1 / 25_600)])
    assert "Delta_X\t3.906250E-05\t" in text
    file = tmp_path / "rec.lvm"
    file.write_text(text.replace("Delta_X\t3.906250E-05\t", "Delta_X\tabc\t"), encoding="utf-8")
    number = 1 + text.splitlines().index("Delta_X\t3.906250E-05\t")
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    line = _one_error_line(err)
    assert line == (
        f"error: {file}: line {number}: field 'Delta_X' holds 'abc', not a number; LabVIEW "
        f"writes a number there (the file was edited or damaged)"
    )
    assert "<ast" not in line


def test_several_channels_of_a_file_under_one_channel_field_are_warned_of(sdt_main, tmp_path):
    from nptdms import ChannelObject, TdmsWriter

    props = {"wf_increment": 1 / 25_600, "unit_string": "g"}
    for run in ("r1", "r2"):
        folder = tmp_path / "daq" / "healthy" / run
        folder.mkdir(parents=True)
        with TdmsWriter(folder / "ch1.tdms") as writer:
            writer.write_segment(
                [
                    ChannelObject("Dev1", ai, np.zeros(4096), properties=props)
                    for ai in ("ai0", "ai1")
                ]
            )
    out = tmp_path / "m.csv"
    code, stdout, err = sdt_main(
        "dataset", "manifest", str(tmp_path / "daq"),
        "--pattern", "{condition}/{run}/{channel}.tdms", "--out", str(out),
    )  # fmt: skip
    assert code == 0, err
    assert "4 rows from 2 files (2 recordings)" in stdout
    warnings = [line for line in err.splitlines() if line.startswith("warning: ")]
    assert warnings == [
        f"warning: daq/healthy/{run}/ch1.tdms: signals 'Dev1/ai0', 'Dev1/ai1' of different names "
        f"are read as 2 acquisitions of one channel 'ch1' (the pattern's {{channel}}); if they "
        f"are different channels or axes, leave {{channel}} out of --pattern so that each "
        f"becomes a channel of its own"
        for run in ("r1", "r2")
    ]
    # without {channel}, each signal is a channel of its own and nothing is merged
    code, stdout, err = sdt_main(
        "dataset", "manifest", str(tmp_path / "daq"), "--pattern", "{condition}/{run}/ch1.tdms",
        "--out", str(tmp_path / "m2.csv"),
    )  # fmt: skip
    assert code == 0 and "warning" not in err
    assert "4 rows from 2 files (4 recordings)" in stdout


def test_a_matlab_n_by_3_matrix_is_noted_as_three_acquisitions(sdt_main, tmp_path):
    file = tmp_path / "xyz.mat"
    scipy.io.savemat(file, {"acc": np.random.default_rng(0).normal(size=(20_000, 3))})
    code, out, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0, err
    assert "│acc│-│3│20000│" in "".join(out.split())
    assert err.splitlines() == [
        f"note: {file}: variable 'acc' is a 20,000 x 3 matrix, read as 3 acquisitions of one "
        f"signal (20,000 samples each, the longer axis is time); if its columns are different "
        f"axes or sensors, save each as a variable"
    ]
    scipy.io.savemat(file, {"acc": np.zeros(20_000)})  # one column: nothing to note
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0 and err == ""
