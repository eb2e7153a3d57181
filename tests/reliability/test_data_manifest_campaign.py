"""``sdt dataset manifest`` on a real campaign's files: names, units and healthy folders.

Each case failed on main before round 4 of issue 41 (items 5, 10, 14): a
channel name padded with spaces, as LabVIEW writes it, was written to the
manifest as it is and looked up stripped (0 recordings); a TDMS file's
temperature, voltage, pressure and force channels were written with empty
units and the manifest reader refused the whole manifest; a healthy folder
without a severity could not share one pattern with the fault folders.
Files are written by the format's own library (npTDMS's ``TdmsWriter``), or,
for LVM, which no library writes, in the layout of LabVIEW's own file in
tests/data/readers/short.lvm.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data import open_manifest

LVM_HEADER = """LabVIEW Measurement\t
Writer_Version\t2
Reader_Version\t2
Separator\tTab
Decimal_Separator\t.
Multi_Headings\tYes
X_Columns\tNo
Time_Pref\tAbsolute
Operator\tsdt
Date\t2024/05/02
Time\t10:15:00.0
***End_of_Header***\t
\t
Channels\t{k}\t\t
Samples\t{samples}\t
Date\t{dates}\t
Time\t{times}\t
Y_Unit_Label\t{units}\t
X_Dimension\t{dims}\t
X0\t{x0}\t
Delta_X\t{dx}\t
***End_of_Header***\t\t\t
X_Value\t{names}\tComment
"""


def _lvm(file: Path, channels: dict[str, np.ndarray], units: str = "g") -> None:
    """An LVM as LabVIEW writes it (tabs, two headers, an empty X column), rate 1 kHz."""
    k, n = len(channels), len(next(iter(channels.values())))
    each = lambda text: "\t".join([text] * k)  # noqa: E731
    header = LVM_HEADER.format(
        k=k, samples=each(str(n)), dates=each("2024/05/02"), times=each("10:15:00.0"),
        units=each(units), dims=each("Time"), x0=each("0.0000000000000000E+0"),
        dx=each("1.000000E-3"), names="\t".join(channels),
    )  # fmt: skip
    rows = np.column_stack(list(channels.values()))
    body = "".join("\t" + "\t".join(f"{v:.6f}" for v in row) + "\n" for row in rows)
    file.parent.mkdir(parents=True, exist_ok=True)
    file.write_text(header + body, encoding="ascii")


def _tdms(file: Path, channels: list[tuple[str, str, np.ndarray, str]], rate=1000.0) -> None:
    """(group, channel, samples, unit_string) written with npTDMS's TdmsWriter."""
    from nptdms import ChannelObject, TdmsWriter

    file.parent.mkdir(parents=True, exist_ok=True)
    with TdmsWriter(file) as writer:
        writer.write_segment(
            [ChannelObject(g, c, data, properties={"wf_increment": 1 / rate, "unit_string": u})
             for g, c, data, u in channels]
        )  # fmt: skip


def _rows(path: Path) -> list[dict[str, str]]:
    with open(path, encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def _manifest(sdt_main, tree: Path, pattern: str, out: Path, *extra: str):
    return sdt_main("dataset", "manifest", str(tree), "--pattern", pattern, "--out", str(out),
                    *extra)  # fmt: skip


PADDED = "       Acceleration"  # as the LabVIEW file names its channel


def test_a_padded_channel_name_is_written_and_read_as_the_file_names_it(
    tmp_path, sdt_main, readers
):
    import lvm_read

    for k, folder in enumerate(["healthy", "fault1", "fault2"]):
        _lvm(tmp_path / "tree" / folder / "r1.lvm", {PADDED: np.sin(np.arange(400) * k / 10)})
    out = tmp_path / "m.csv"
    code, _, err = _manifest(sdt_main, tmp_path / "tree", "{condition}/{run}.lvm", out)
    assert code == 0, err
    assert {r["variable"] for r in _rows(out)} == {PADDED}  # as the file names it
    assert {r["channel"] for r in _rows(out)} == {"Acceleration"}  # a label, stripped
    recordings = {r.condition: r for r in open_manifest(out, readers=readers).recordings()}
    assert len(recordings) == 3  # main: 0, each row skipped "no signal 'Acceleration'"
    for folder, rec in recordings.items():
        reference = lvm_read.read(str(tmp_path / "tree" / folder / "r1.lvm"),
                                  read_from_pickle=False, dump_file=False)  # fmt: skip
        column = reference[0]["Channel names"].index(PADDED)
        np.testing.assert_array_equal(rec.load(), [reference[0]["data"][:, column]])


def test_a_name_typed_without_its_padding_reads_the_one_signal_it_can_be(tmp_path, readers):
    """Exact names first: ``'  a'`` and ``'a'`` are two signals; a typed ``'Acceleration'``
    reads the padded channel only where no channel has that exact name."""
    padded, plain = np.arange(300.0), np.full(300, -2.0)
    _lvm(tmp_path / "two.lvm", {PADDED: padded, "Acceleration": plain})
    _lvm(tmp_path / "one.lvm", {PADDED: padded + 1})
    header = "path,sampling_rate_hz,condition,severity,recording_id,channel,variable\n"
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        header
        + f'two.lvm,,healthy,,r1,padded,"{PADDED}"\n'
        + "two.lvm,,healthy,,r1,plain,Acceleration\n"
        + "one.lvm,,fault,1,r2,typed,Acceleration \n",  # typed, a trailing space too
        encoding="utf-8",
    )
    loaded = {r.channel: r.load() for r in open_manifest(manifest, readers=readers).recordings()}
    np.testing.assert_array_equal(loaded["padded"], [padded])
    np.testing.assert_array_equal(loaded["plain"], [plain])
    np.testing.assert_array_equal(loaded["typed"], [padded + 1])


def test_one_signal_named_two_ways_on_two_rows_is_refused(tmp_path, readers):
    from sdt_framework.errors import SDTError

    _lvm(tmp_path / "one.lvm", {PADDED: np.arange(300.0)})
    header = "path,sampling_rate_hz,condition,severity,recording_id,channel,variable\n"
    manifest = tmp_path / "m.csv"
    manifest.write_text(header + f'one.lvm,,healthy,,r1,a,"{PADDED}"\n'
                        + "one.lvm,,fault,1,r2,a,Acceleration\n", encoding="utf-8")  # fmt: skip
    with pytest.raises(SDTError, match=r"line 2 and line 3 both read .*one\.lvm \(variable"):
        open_manifest(manifest, readers=readers)


def test_channels_that_are_no_acceleration_are_left_out_and_counted(tmp_path, sdt_main, readers):
    from nptdms import TdmsFile

    tree = tmp_path / "tree"
    others = [("Env", "Temp 1", "degC"), ("Env", "Temp 2", "degC"), ("Env", "Supply", "V"),
              ("Env", "Pressure", "hPa"), ("Load", "Cell", "pounds")]  # fmt: skip
    for k, folder in enumerate(["healthy", "bearing"]):
        _tdms(tree / folder / "r1.tdms", [
            ("Acc", "x", np.full(500, k + 0.5), "g"), ("Acc", "y", np.full(500, -k - 0.5), "g"),
            *[(g, c, np.full(500, 20.0), u) for g, c, u in others]])  # fmt: skip
    _tdms(tree / "healthy" / "r2.tdms", [("Env", "Temp 1", np.full(500, 21.0), "degC"),
                                         ("Env", "Supply", np.full(500, 24.0), "V")])  # fmt: skip
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(sdt_main, tree, "{condition}/{run}.tdms", out)
    assert code == 0, err
    assert "wrote" in printed and "4 rows from 2 files (4 recordings); 1 not used" in printed
    assert (
        "note: 12 signals skipped: not an acceleration unit ('degC': 5, 'V': 3, 'hPa': 2, "
        "'pounds': 2), in 3 files (e.g. 'Env/Temp 1' in bearing/r1.tdms)" in err
    )
    assert (
        "not used: healthy/r2.tdms: no acceleration signal: its 2 signals are in 'degC', 'V'" in err
    )
    rows = _rows(out)
    assert {(r["variable"], r["units"]) for r in rows} == {("Acc/x", "g"), ("Acc/y", "g")}
    recordings = open_manifest(
        out, readers=readers
    ).recordings()  # main: refused, "'degC', not an acceleration"
    assert len(recordings) == 4
    for rec in recordings:
        group, channel = rec.channel.split("-")
        file = tree / (rec.condition) / "r1.tdms"
        np.testing.assert_array_equal(rec.load(), [TdmsFile.read(file)[group][channel][:]])


def _campaign(root: Path, layout: str) -> dict[str, float]:
    """NPY runs of a campaign: healthy folders without a severity; the value of each run."""
    values = {}
    for k, (condition, severity) in enumerate(
        [("healthy", None), ("healthy", None), ("bearing", 1), ("bearing", 2), ("imbalance", 3)]
    ):
        run = f"r{k}"
        if severity is None:
            folder = condition
        else:
            folder = f"{condition} {severity}" if layout == "name" else f"{condition}/{severity}"
        values[run] = float(k)
        file = root / folder / run / "ch1.npy"
        file.parent.mkdir(parents=True, exist_ok=True)
        np.save(file, np.full(256, float(k)))
    return values


@pytest.mark.parametrize(
    ("layout", "pattern"),
    [
        ("name", "{condition} {severity?}/{run}/{channel}.npy"),  # healthy beside bearing 2
        ("folder", "{condition}/{severity?}/{run}/{channel}.npy"),  # healthy/r0, bearing/2/r3
    ],
)
def test_one_pattern_reads_healthy_folders_without_a_severity(
    tmp_path, sdt_main, layout, pattern, readers
):
    values = _campaign(tmp_path / "tree", layout)
    out = tmp_path / "m.csv"
    code, printed, err = _manifest(sdt_main, tmp_path / "tree", pattern, out, "--rate-hz", "1000")
    assert code == 0, err  # main: "unknown field(s) {severity?}"
    assert "5 rows from 5 files (5 recordings); 0 not used" in printed
    labels = {r.run: (r.condition, r.severity, float(r.load().mean()))
              for r in open_manifest(out, readers=readers).recordings()}  # fmt: skip
    assert labels == {
        "r0": ("healthy", None, values["r0"]),
        "r1": ("healthy", None, values["r1"]),
        "r2": ("bearing", 1, values["r2"]),
        "r3": ("bearing", 2, values["r3"]),
        "r4": ("imbalance", 3, values["r4"]),
    }


def test_an_optional_field_keeps_the_rules_of_the_field(tmp_path, sdt_main):
    tree = tmp_path / "tree"
    _campaign(tree, "name")
    (tree / "bearing \u0663" / "r9").mkdir(parents=True)  # ARABIC-INDIC DIGIT THREE
    np.save(tree / "bearing \u0663" / "r9" / "ch1.npy", np.zeros(256))
    out = tmp_path / "m.csv"
    pattern = "{condition} {severity?}/{run}/{channel}.npy"
    code, printed, err = _manifest(sdt_main, tree, pattern, out, "--rate-hz", "1000")
    assert code == 0, err
    assert "1 not used" in printed  # not the condition 'bearing ٣' without a severity
    assert "'bearing ٣' does not match '{condition} {severity?}'; {severity} is ASCII" in err
    code, _, err = _manifest(sdt_main, tree, "{condition}/{run?}/{channel}.npy", tmp_path / "n.csv")
    assert code == 2
    assert err.strip().splitlines() == [
        "error: --pattern '{condition}/{run?}/{channel}.npy': {run?} cannot be missing; only "
        "{machine?}, {speed?}, {severity?} may be (write {run})"
    ]


def _examples(help_text: str) -> list[list[str]]:
    """The example command lines of a help text, each as the words a shell would pass."""
    import re
    import shlex

    after = help_text.split("Example:", 1)[1].replace("\\\n", " ")
    lines = [line.strip() for line in after.splitlines()]
    return [shlex.split(line, comments=True) for line in lines if re.match(r"(python|sdt) ", line)]


def test_every_help_example_makes_a_manifest_the_benchmark_accepts(tmp_path, monkeypatch, sdt_main):
    """Run as written, in order, from a folder holding examples/ (main's example wrote
    UFF channels in Pa, which the benchmark then refused)."""
    import subprocess
    import sys

    from sdt_framework.cli.dataset_files import manifest

    root = Path(__file__).resolve().parents[2]
    (tmp_path / "examples").symlink_to(root / "examples")
    (tmp_path / "tests").symlink_to(root / "tests")  # main's example read tests/data
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))
    made, benchmarked = [], []
    for words in _examples(manifest.__doc__ or ""):
        if words[0] == "python":
            run = subprocess.run([sys.executable, *words[1:]], capture_output=True, text=True)
            assert run.returncode == 0, run.stderr
            continue
        if words[1] == "benchmark":  # as written, kept small: one classifier, one scenario
            words += ["--classifiers", "lr", "--scenarios", "forward", "--sensors", "adxl345",
                      "--no-report", "--out", f"results{len(benchmarked)}"]  # fmt: skip
            benchmarked.append(words[words.index("--data") + 1])
        code, _, err = sdt_main(*words[1:])
        assert code == 0, (words, err)
        if words[1:3] == ["dataset", "manifest"]:
            made.append(words[words.index("--out") + 1])
    assert made
    for out in made:
        if out not in benchmarked:
            code, _, err = sdt_main("benchmark", "--quick", "--data", out, "--classifiers", "lr",
                                    "--scenarios", "forward", "--sensors", "adxl345",
                                    "--no-report", "--out", f"results-{out}")  # fmt: skip
            assert code == 0, (out, err)
