"""Output paths of the file commands: checked before the work, never an input, one line.

On main before the reliability round ``sdt degrade a.npy --out a.npy``
replaced the input with its own degraded copy, ``dataset synth`` wrote into a
folder of recordings, a bad ``--plot`` path failed with a traceback after the
whole computation, and an OS error (read-only folder, folder as output) was
a traceback. ``/sys`` is a folder that nobody, root included, can create
files in: it stands for a read-only folder.
"""

from __future__ import annotations

import errno
from pathlib import Path

import numpy as np
import pytest

READ_ONLY = Path("/sys")


def one_line_error(code: int, err: str) -> bool:
    return (
        code == 2 and err.count("\n") == 1 and err.startswith("error:") and "Traceback" not in err
    )


@pytest.fixture
def signal(tmp_path: Path) -> Path:
    path = tmp_path / "sig.npy"
    np.save(path, np.sin(np.arange(8000) / 7.0))
    return path


def degrade_args(src: Path | str, out: Path | str) -> list[str]:
    return ["degrade", str(src), "--sensor", "adxl345", "--fs", "20000", "--out", str(out)]


@pytest.mark.parametrize("form", ["same", "dotted", "linked-folder"])
def test_degrade_refuses_its_input_as_output(
    sdt_main, monkeypatch, capsys, signal: Path, form
) -> None:
    before = signal.read_bytes()
    (signal.parent / "sub").mkdir()
    (signal.parent / "link").symlink_to(signal.parent)
    out = {
        "same": signal,
        "dotted": signal.parent / "sub" / ".." / signal.name,
        "linked-folder": signal.parent / "link" / signal.name,
    }[form]
    code, _, err = sdt_main(*degrade_args(signal, out))
    assert one_line_error(code, err) and "is the input file" in err
    assert signal.read_bytes() == before


def test_features_extract_refuses_a_link_to_its_input(
    sdt_main, monkeypatch, capsys, signal: Path
) -> None:
    before = signal.read_bytes()
    out = signal.parent / "features.csv"
    out.symlink_to(signal)
    code, _, err = sdt_main("features", "extract", str(signal), "--fs", "3200", "--out", str(out))
    assert one_line_error(code, err) and "is the input file" in err
    assert signal.read_bytes() == before and out.is_symlink()


def test_synth_refuses_a_folder_of_recordings_unless_overwrite(
    sdt_main, monkeypatch, capsys, tmp_path: Path
) -> None:
    mine = tmp_path / "data" / "Vibration" / "Motor-4" / "70" / "my run" / "mine.csv"
    mine.parent.mkdir(parents=True)
    mine.write_text("time,0\n0,1\n")
    args = ["dataset", "synth", "--out", str(tmp_path / "data"), "--duration", "0.25"]
    code, _, err = sdt_main(*args)
    assert one_line_error(code, err) and "already holds recordings (1 files" in err
    assert "--overwrite" in err
    assert sorted(p.name for p in (tmp_path / "data").rglob("*.csv")) == ["mine.csv"]
    code, _, err = sdt_main(*args, "--overwrite")
    assert code == 0, err
    # the default's 255 recordings (no Motor-4 cavitation suction 2, as in the archive) + mine
    assert len(list((tmp_path / "data").rglob("*.csv"))) == 256
    assert mine.read_text() == "time,0\n0,1\n"
    assert "1 other file(s)" in err and "left as they were" in err


def test_synth_help_shows_overwrite_with_an_example(sdt_main, monkeypatch, capsys) -> None:
    code, out, _ = sdt_main("dataset", "synth", "--help")
    assert code == 0 and "--overwrite" in out and "sdt dataset synth --out" in out


@pytest.mark.parametrize(
    ("plot", "expected"),
    [
        ("{tmp}/noise.txt", "unsupported extension '.txt'; use one of .png, .pdf, .svg"),
        ("{tmp}", "is a folder"),
        ("/sys/noise.png", "cannot write in /sys"),
        ("/sys/no/such/folder/noise.png", "cannot write in /sys"),
        ("{tmp}/sig.npy/noise.png", "sig.npy is a file, not a folder"),
    ],
    ids=["extension", "folder", "read-only", "uncreatable-folder", "file-in-the-way"],
)
def test_bad_plot_path_is_refused_before_the_computation(
    sdt_main, monkeypatch, capsys, tmp_path: Path, signal: Path, plot: str, expected: str
) -> None:
    calls: list[object] = []
    monkeypatch.setattr("sdt_framework.validation.noise_check", lambda *a, **k: calls.append(a))
    path = plot.format(tmp=tmp_path)
    code, _, err = sdt_main("validate-noise", "--sensor", "adxl345", "--plot", path)
    assert one_line_error(code, err) and f"--plot {path}" in err and expected in err
    assert calls == []  # refused before any computation


def test_plot_into_a_new_folder_is_created(sdt_main, monkeypatch, capsys, tmp_path: Path) -> None:
    png = tmp_path / "figures" / "noise.png"
    code, _, err = sdt_main("validate-noise", "--sensor", "adxl345", "--plot", str(png))
    assert code == 0, err
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize(
    ("command", "expected"),
    [
        (lambda s, t: degrade_args(s, READ_ONLY / "o.npy"), "cannot write in /sys"),
        (lambda s, t: degrade_args(s, t), "is a folder"),
        (lambda s, t: degrade_args(s, t / "o.npy"), "is a folder"),
        (lambda s, t: degrade_args(t / "missing.npy", t / "x.npy"), "no such file"),
        (lambda s, t: degrade_args(t, t / "x.npy"), "is a folder"),
        (
            lambda s, t: ["features", "extract", str(s), "--fs", "3200", "--out", "/sys/f.csv"],
            "cannot write in /sys",
        ),
        (
            lambda s, t: (
                ["features", "extract", f"{t}/gone.npy", "--fs", "3200", "--out", f"{t}/f.csv"]
            ),
            "no such file",
        ),
        (lambda s, t: ["dataset", "synth", "--out", str(s), "--duration", "0.25"], "is a file"),
        (
            lambda s, t: ["dataset", "synth", "--out", "/sys/synth", "--duration", "0.25"],
            "cannot write in /sys",
        ),
        (
            lambda s, t: (
                ["validate-noise", "--sensor", "adxl345", "--recording", str(t / "gone.csv")]
            ),
            "no such file",
        ),
    ],
    ids=[
        "degrade-read-only",
        "degrade-out-folder",
        "degrade-out-folder-named-npy",
        "degrade-missing-input",
        "degrade-input-folder",
        "features-read-only",
        "features-missing-input",
        "synth-out-is-file",
        "synth-read-only",
        "noise-missing-recording",
    ],
)
def test_os_errors_are_one_line(
    sdt_main, monkeypatch, capsys, tmp_path: Path, signal, command, expected
):
    (tmp_path / "o.npy").mkdir()
    code, _, err = sdt_main(*command(signal, tmp_path))
    assert one_line_error(code, err) and expected in err, err


def test_disk_full_while_writing_leaves_nothing(
    sdt_main, monkeypatch, capsys, tmp_path: Path, signal
):
    """ENOSPC in the middle of the write: one line, no output, no temporary file left."""
    import sdt_framework.cli.signal_io as files

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device", str(args[0].name))

    monkeypatch.setattr(files.np, "save", full)
    out = tmp_path / "out" / "y.npy"
    code, _, err = sdt_main(*degrade_args(signal, out))
    assert one_line_error(code, err) and "disk is full" in err
    assert list(out.parent.iterdir()) == []
