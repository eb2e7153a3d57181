"""``sdt dataset manifest`` over hostile trees: nothing lost, nothing merged, one line to refuse.

Each case failed on main before round 4 (issue 39, item 10): two TDMS channels
whose names meet after ``/`` becomes ``-`` were one recording; a symlinked run
folder, a broken link and a FIFO were left out under "0 files not matched"; run
names reused under each condition folder made one recording of all; a rate of
0, -1, nan or inf was written; ``{cond}`` was reported as a missing
``{condition}``; an Arabic-Indic digit was taken as severity 3.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data import open_manifest


def _tdms(file: Path, signals: dict[tuple[str, str], np.ndarray], rate: float = 1000.0) -> None:
    from nptdms import ChannelObject, TdmsWriter

    file.parent.mkdir(parents=True, exist_ok=True)
    props = {"wf_increment": 1 / rate, "unit_string": "g"}
    with TdmsWriter(file) as writer:
        writer.write_segment(
            [ChannelObject(g, c, data, properties=props) for (g, c), data in signals.items()]
        )


def _npy(file: Path, value: float, n: int = 256) -> None:
    file.parent.mkdir(parents=True, exist_ok=True)
    np.save(file, np.full(n, value))


def _rows(path: Path) -> list[dict[str, str]]:
    with open(path, encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def _manifest(sdt_main, tree: Path, pattern: str, out: Path, *extra: str):
    """``sdt dataset manifest TREE --pattern PATTERN --out OUT`` (NPY trees: 1 kHz)."""
    rate = () if pattern.endswith(".tdms") or "--rate-hz" in extra else ("--rate-hz", "1000")
    return sdt_main("dataset", "manifest", str(tree), "--pattern", pattern, "--out", str(out),
                    *rate, *extra)  # fmt: skip


def _one_error_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


def test_channels_meeting_after_slash_becomes_dash_stay_two_recordings(tmp_path, sdt_main, readers):
    first, second = np.arange(300.0), np.full(300, -7.0)
    _tdms(tmp_path / "tree/healthy/r1/f.tdms", {("g", "a-b"): first, ("g-a", "b"): second})
    _tdms(tmp_path / "tree/healthy/r2/f.tdms", {("g", "a-b"): first + 1})  # one of the two
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(sdt_main, tmp_path / "tree", "{condition}/{run}/f.tdms", out)
    assert code == 0, err
    assert "3 rows from 2 files (3 recordings)" in printed
    assert "'g-a/b' -> g-a-b~1, 'g/a-b' -> g-a-b~2" in err  # said, not silent
    channels = {(r["recording_id"], r["variable"]): r["channel"] for r in _rows(out)}
    assert channels == {  # by variable name, the same in every run
        ("r1", "g-a/b"): "g-a-b~1",
        ("r1", "g/a-b"): "g-a-b~2",
        ("r2", "g/a-b"): "g-a-b~2",
    }
    recordings = {(r.run, r.channel): r for r in open_manifest(out, readers=readers).recordings()}
    assert len(recordings) == 3
    np.testing.assert_array_equal(recordings["r1", "g-a-b~2"].load(), [first])
    np.testing.assert_array_equal(recordings["r1", "g-a-b~1"].load(), [second])
    np.testing.assert_array_equal(recordings["r2", "g-a-b~2"].load(), [first + 1])


def test_symlinked_run_broken_link_and_fifo_are_used_or_named(tmp_path, sdt_main, readers):
    tree = tmp_path / "tree"
    _npy(tree / "healthy/h1/ch1.npy", 1.0)
    _npy(tree / "fault/f1/ch1.npy", 2.0)
    _npy(tmp_path / "elsewhere/f2/ch1.npy", 3.0)  # a run folder kept on another disk
    os.symlink(tmp_path / "elsewhere/f2", tree / "fault/f2")
    os.symlink("gone.npy", tree / "healthy/h1/ch2.npy")
    os.mkfifo(tree / "fault/f1/ch2.npy")
    os.symlink("/dev/zero", tree / "fault/f1/ch3.npy")  # never ends: must not be opened
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(sdt_main, tree, "{condition}/{run}/{channel}.npy", out)
    assert code == 0, err
    assert "3 rows from 3 files (3 recordings); 3 not used" in printed
    assert "not used: healthy/h1/ch2.npy: broken symbolic link to gone.npy" in err
    assert "not used: fault/f1/ch2.npy: not a regular file (a named pipe)" in err
    assert "not used: fault/f1/ch3.npy: not a regular file (a character device)" in err
    runs = {r.run: float(r.load().mean()) for r in open_manifest(out, readers=readers).recordings()}
    assert runs == {"h1": 1.0, "f1": 2.0, "f2": 3.0}


def test_a_link_loop_and_a_folder_reached_twice_are_named_and_used_once(tmp_path, sdt_main):
    tree = tmp_path / "tree"
    _npy(tree / "healthy/h1/ch1.npy", 1.0)
    _npy(tree / "fault/f1/ch1.npy", 2.0)
    os.symlink("..", tree / "healthy/h1/up")  # a loop: h1/up/h1/up/...
    os.symlink("../healthy/h1", tree / "fault/a-copy")  # h1 again, sorted before f1
    os.symlink("ch1.npy", tree / "fault/f1/ch9.npy")  # the same samples under a second name
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(sdt_main, tree, "{condition}/{run}/{channel}.npy", out)
    assert code == 0, err
    assert "2 rows from 2 files (2 recordings); 3 not used" in printed
    assert "not used: healthy/h1/up/: symbolic link to a folder above it (a loop)" in err
    assert "not used: fault/a-copy/: the same folder as healthy/h1/" in err
    assert "not used: fault/f1/ch9.npy: the same file as fault/f1/ch1.npy" in err
    assert [(r["condition"], r["recording_id"]) for r in _rows(out)] == [
        ("fault", "f1"),
        ("healthy", "h1"),
    ]


def test_run_names_reused_under_each_condition_are_separate_recordings(tmp_path, sdt_main, readers):
    tree = tmp_path / "tree"
    levels = {"healthy -": 0.0, "bearing 1": 1.0, "bearing 2": 2.0, "misalign 1": 3.0}
    for folder, value in levels.items():
        for k in (1, 2, 3):
            _npy(tree / folder / f"run{k}" / "ch1.npy", value + k / 10)
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(
        sdt_main, tree, "{condition} {severity}/{run}/{channel}.npy", out
    )
    assert code == 0, err
    assert "12 rows from 12 files (12 recordings)" in printed
    assert "each recording_id is built from the labels" in err
    recordings = open_manifest(out, readers=readers).recordings()
    ids = {r.recording_id: (r.condition, r.severity, float(r.load().mean())) for r in recordings}
    assert len(ids) == 12
    assert ids["machine/bearing 2/run3/ch1"] == ("bearing", 2, pytest.approx(2.3))
    assert ids["machine/healthy/run1/ch1"] == ("healthy", None, pytest.approx(0.1))


def test_one_run_name_under_one_condition_keeps_its_name(tmp_path, sdt_main):
    """No clash, no change: ids stay the run names (docs/data.md's tree)."""
    tree = tmp_path / "tree"
    _npy(tree / "healthy/h1/ch1.npy", 1.0)
    _npy(tree / "fault/f1/ch1.npy", 2.0)
    out = tmp_path / "m.csv"
    code, _, err = _manifest(sdt_main, tree, "{condition}/{run}/{channel}.npy", out)
    assert code == 0 and "note" not in err, err
    assert [r["recording_id"] for r in _rows(out)] == ["f1", "h1"]


@pytest.mark.parametrize("rate", ["0", "-1", "nan", "inf"])
def test_a_rate_that_is_no_rate_is_refused(tmp_path, sdt_main, rate):
    _npy(tmp_path / "tree/healthy/h1/ch1.npy", 1.0)
    out = tmp_path / "m.csv"
    code, _, err = _manifest(
        sdt_main, tmp_path / "tree", "{condition}/{run}/{channel}.npy", out, "--rate-hz", rate
    )
    assert code == 2
    assert _one_error_line(err) == f"error: --rate-hz {rate}: give a finite number above 0"
    assert not out.exists()


@pytest.mark.parametrize(
    ("pattern", "named"),
    [
        ("{cond}/{run}/{channel}.npy", "unknown field(s) {cond}; the fields are {machine}, "),
        ("{condition}/{Run}/{channel}.npy", "unknown field(s) {Run}; the fields are"),
        ("{condition/{run}/{channel}.npy", "a '{' without its pair"),
    ],
)
def test_a_mistyped_field_is_named_with_the_known_ones(tmp_path, sdt_main, pattern, named):
    _npy(tmp_path / "tree/healthy/h1/ch1.npy", 1.0)
    code, _, err = _manifest(sdt_main, tmp_path / "tree", pattern, tmp_path / "m.csv")
    assert code == 2
    line = _one_error_line(err)
    assert named in line and "{severity}, {run}, {channel}" in line


def test_a_severity_in_arabic_indic_digits_is_no_level(tmp_path, sdt_main):
    tree = tmp_path / "tree"
    _npy(tree / "bearing 2/r1/ch1.npy", 1.0)
    _npy(tree / "bearing \u0663/r2/ch1.npy", 2.0)  # ARABIC-INDIC DIGIT THREE
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(
        sdt_main, tree, "{condition} {severity}/{run}/{channel}.npy", out
    )
    assert code == 0, err
    assert "1 not used" in printed
    assert "{severity} is ASCII digits 0-9 or '-'" in err
    assert [(r["severity"], r["recording_id"]) for r in _rows(out)] == [("2", "r1")]


def test_a_manifest_severity_or_rate_in_other_digits_is_refused(tmp_path, readers):
    from sdt_framework.errors import SDTError

    _npy(tmp_path / "a.npy", 1.0)
    header = "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
    for row, field in (
        ("a.npy,1000,bearing,\u0663,r1,ch1\n", "'severity'"),
        ("a.npy,\u0661\u0660\u0660\u0660,bearing,3,r1,ch1\n", "'sampling_rate_hz'"),
    ):
        (tmp_path / "m.csv").write_text(header + row, encoding="utf-8")
        with pytest.raises(SDTError, match=f"line 2: field {field}"):
            open_manifest(tmp_path / "m.csv", readers=readers)
