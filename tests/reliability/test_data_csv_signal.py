"""One CSV rule for signal files, used by the manifest reader and by ``sdt degrade``.

On main before the reliability round ``sdt degrade`` read a ``time,acc`` CSV
as 40 000 acquisitions of two samples (rows = acquisitions, header skipped),
a header-only file as an empty signal (after a numpy warning), and a byte
that is not UTF-8 as a codec message without a line number.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.data import open_manifest
from sdt_framework.registry import build_registry

FS = 20000.0


@pytest.fixture
def acc() -> np.ndarray:
    t = np.arange(40000) / FS
    return 0.5 * np.sin(2 * np.pi * 120 * t) + 0.1 * np.cos(2 * np.pi * 900 * t)


def test_time_acc_csv_is_one_acquisition_in_degrade(
    sdt_main, monkeypatch, capsys, tmp_path, acc
) -> None:
    src, out = tmp_path / "pump.csv", tmp_path / "out.npy"
    t = np.arange(acc.size) / FS
    np.savetxt(src, np.c_[t, acc], delimiter=",", fmt="%.17g", header="time,acc", comments="")
    code, stdout, err = sdt_main(
        *("degrade", str(src), "--sensor", "adxl345", "--fs", "20000", "--no-noise"),
        *("--out", str(out)),
    )
    assert code == 0, err
    expected, _ = degrade(acc, FS, build_registry().sensor("adxl345"), noise=False)
    np.testing.assert_array_equal(np.load(out), expected)  # one 1-D acquisition
    assert "1 acquisition(s) x 40000 samples" in stdout
    notes = [line for line in err.splitlines() if line.startswith("note:")]
    assert len(notes) == 1 and str(src) in notes[0] and "'time'" in notes[0]


def test_same_rule_in_manifest_and_degrade(tmp_path: Path, acc: np.ndarray, readers) -> None:
    """A headerless (samples, 2) file: a leading regular time axis is found by value."""
    from sdt_framework.signals.one_signal import open_signal

    src = tmp_path / "s.csv"
    np.savetxt(src, np.c_[np.arange(acc.size) / FS, acc], delimiter=",", fmt="%.17g")
    opened = open_signal(src, build_registry().signal_readers(), rate_hz=FS)
    np.testing.assert_array_equal(opened.read_g(), [acc])
    note = opened.info.note
    assert note is not None and "column 1 read as time" in note
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
        "s.csv,20000,healthy,,r1,ch1\n"
    )
    (rec,) = open_manifest(manifest, readers=readers).recordings()
    np.testing.assert_array_equal(rec.load(), [acc])


def test_rows_as_acquisitions_still_read_as_rows(tmp_path: Path, acc: np.ndarray) -> None:
    """``numpy.savetxt`` of (2, n): the longer axis is time, so two acquisitions."""
    from sdt_framework.signals.csv_rule import read_csv_signal

    x = np.vstack([acc, -acc])
    np.savetxt(tmp_path / "x.csv", x, delimiter=",", fmt="%.17g")
    parsed = read_csv_signal(tmp_path / "x.csv")
    np.testing.assert_array_equal(parsed.data, x)
    assert parsed.note is None


def test_a_ramp_alone_is_a_signal_not_a_time_axis(tmp_path: Path) -> None:
    from sdt_framework.signals.csv_rule import read_csv_signal

    np.savetxt(tmp_path / "ramp.csv", np.arange(100.0), fmt="%g")
    parsed = read_csv_signal(tmp_path / "ramp.csv")
    np.testing.assert_array_equal(parsed.data, [np.arange(100.0)])
    assert parsed.note is None


def test_header_only_file_is_refused(sdt_main, monkeypatch, capsys, tmp_path: Path) -> None:
    src = tmp_path / "hdr.csv"
    src.write_text("time,acc\n")
    code, _, err = sdt_main(
        *("degrade", str(src), "--sensor", "adxl345", "--fs", "20000"),
        *("--out", str(tmp_path / "o.npy")),
    )
    assert code == 2 and err.count("\n") == 1 and "Traceback" not in err
    assert f"{src}: line 1 is a header" in err and "no data row" in err
    assert not (tmp_path / "o.npy").exists()


@pytest.mark.parametrize(
    ("content", "expected"),
    [
        (b"acc\n0.1\n0.2\n\xff\xfe\n0.3\n", "line 4: not UTF-8 text (byte 0xff"),
        (b"\xe9t\xe9,acc\n0.1,0.2\n", "line 1: not UTF-8 text (byte 0xe9"),
        (b"0.1,0.2\n0.3\n", "line 2: expected 2 values, found 1"),
        (b"a,b\n0.1,\n", "line 2, column 'b': empty value"),
        (b"0.1;0.2\n0.3;0.4\n", "'0.1;0.2' is not a number; separate values with ','"),
        (b"a\n0.1\nnan\n", "line 3, column 'a': non-finite value 'nan'"),
        (b"", "no data (0 bytes)"),
    ],
    ids=["latin-1-body", "latin-1-header", "ragged", "empty-cell", "semicolons", "nan", "empty"],
)
def test_bad_signal_file_is_one_line_naming_file_and_line(
    sdt_main, monkeypatch, capsys, tmp_path: Path, content: bytes, expected: str, readers
) -> None:
    src = tmp_path / "sig.csv"
    src.write_bytes(content)
    manifest = tmp_path / "m.csv"
    manifest.write_text(
        "path,sampling_rate_hz,condition,severity,recording_id,channel\n"
        "sig.csv,20000,healthy,,r1,ch1\n"
    )
    dataset = open_manifest(manifest, readers=readers, validate=True)
    (skip,) = dataset.skipped
    assert skip.reason.startswith(f"{src}: ") and expected in skip.reason
    code, _, err = sdt_main(
        *("degrade", str(src), "--sensor", "adxl345", "--fs", "20000"),
        *("--out", str(tmp_path / "o.npy")),
    )
    assert code == 2 and err.count("\n") == 1 and expected in err and "Traceback" not in err
