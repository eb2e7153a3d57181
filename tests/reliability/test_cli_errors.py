"""Every environment error reaching the top of `sdt` is one line with exit 2; Ctrl-C is one
line with exit 130; a genuine bug is an `internal error:` line with exit 70 (its traceback
under SDT_DEBUG=1, as for every error).

Real failures are used where the operating system produces them for any user (a file where
a folder is expected, a folder where a file is expected); the others (permission denied,
disk full, out of memory, Ctrl-C) are injected into a command, since they cannot be made
to happen on demand, and the whole `main()` entry point then runs as a user would run it.
"""

from __future__ import annotations

import errno
import signal
import sys
from pathlib import Path

import numpy as np
import pytest

import sdt_framework.cli.sensors as sensors_cli
from sdt_framework.cli.main import main


def run_main(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture, *args: str):
    """`main()` in this process with ``args``: (exit status, stdout, stderr)."""
    monkeypatch.setattr(sys, "argv", ["sdt", *args])
    with pytest.raises(SystemExit) as exit_info:
        main()
    out = capsys.readouterr()
    return exit_info.value.code, out.out, out.err


def inject(monkeypatch: pytest.MonkeyPatch, exc: BaseException) -> None:
    """Make `sdt sensors list` fail with ``exc`` when it asks for the registry."""

    def failing(ctx: object) -> None:
        raise exc

    monkeypatch.setattr(sensors_cli, "registry", failing)


@pytest.fixture
def signal_file(tmp_path: Path) -> Path:
    path = tmp_path / "sig.npy"
    np.save(path, np.random.default_rng(0).normal(size=4000))
    return path


def one_error_line(stderr: str) -> str:
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert len(lines) == 1, stderr
    assert "Traceback" not in stderr
    assert lines[0].startswith("error: ")
    return lines[0]


def test_out_under_a_file_is_one_line_naming_the_path(signal_file, tmp_path, monkeypatch, capsys):
    blocker = tmp_path / "not_a_folder"
    blocker.write_text("x")
    out = str(blocker / "features.csv")
    args = ("features", "extract", str(signal_file), "--fs", "3200", "--out", out)
    status, _, err = run_main(monkeypatch, capsys, *args)
    assert status == 2
    line = one_error_line(err)
    # the output guard catches it before any write: the path, what is wrong, what to do
    assert f"{blocker} is a file, not a folder" in line and "choose another path" in line


def test_out_that_is_a_folder_is_one_line_naming_it(signal_file, tmp_path, monkeypatch, capsys):
    (tmp_path / "taken.csv").mkdir()
    monkeypatch.chdir(tmp_path)
    args = ("features", "extract", str(signal_file), "--fs", "3200", "--out", "taken.csv")
    status, _, err = run_main(monkeypatch, capsys, *args)
    assert status == 2
    line = one_error_line(err)
    assert "--out taken.csv is a folder" in line and "give a file path" in line


@pytest.mark.parametrize(
    ("code", "needle", "advice"),
    [
        (errno.EACCES, "Permission denied (EACCES)", "check its permissions"),
        (errno.EROFS, "Read-only file system (EROFS)", "choose a writable location"),
        (errno.ENOSPC, "No space left on device (ENOSPC)", "free some space"),
        (errno.ENOENT, "No such file or directory (ENOENT)", "HOME"),
    ],
)
def test_injected_os_errors_are_one_line_with_what_to_do(monkeypatch, capsys, code, needle, advice):
    import os

    inject(monkeypatch, OSError(code, os.strerror(code), "/home/u/.cache/sdt-framework"))
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 2
    line = one_error_line(err)
    assert "'/home/u/.cache/sdt-framework'" in line and needle in line and advice in line


def test_os_error_without_a_path_still_one_line(monkeypatch, capsys):
    inject(monkeypatch, ConnectionRefusedError(errno.ECONNREFUSED, "Connection refused"))
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 2
    assert "ConnectionRefusedError: Connection refused (ECONNREFUSED)" in one_error_line(err)


def test_memory_error_is_one_line(monkeypatch, capsys):
    message = "Unable to allocate 7.28 TiB for an array with shape (1000000000000,)"
    inject(monkeypatch, MemoryError(message))
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 2
    line = one_error_line(err)
    assert "out of memory" in line and "7.28 TiB" in line and "less data" in line


def test_sdt_debug_shows_the_traceback_of_an_os_error(monkeypatch, capsys):
    monkeypatch.setenv("SDT_DEBUG", "1")
    inject(monkeypatch, PermissionError(errno.EACCES, "Permission denied", "/x"))
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 2
    assert "Traceback (most recent call last)" in err and "PermissionError" in err
    assert err.strip().splitlines()[-1].startswith("error: '/x': Permission denied")


def test_a_genuine_bug_is_an_internal_error_with_exit_70(monkeypatch, capsys):
    inject(monkeypatch, ZeroDivisionError("a bug"))
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 70
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert lines[0].startswith("internal error: ZeroDivisionError: a bug")
    assert "this is a bug in sdt" in lines[0]


def test_ctrl_c_is_one_line_and_exit_130(monkeypatch, capsys):
    def interrupted(ctx: object) -> None:
        signal.raise_signal(signal.SIGINT)  # a real SIGINT: Python raises KeyboardInterrupt

    monkeypatch.setattr(sensors_cli, "registry", interrupted)
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 130
    lines = [line for line in err.splitlines() if line.strip()]
    assert lines == ["interrupted: stopped by Ctrl-C."]


def test_ctrl_c_hint_of_a_command_is_kept(monkeypatch, capsys):
    hint = KeyboardInterrupt()
    hint.add_note("Resume with the same command and --out results/x.")
    inject(monkeypatch, hint)
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 130
    assert err.strip() == (
        "interrupted: stopped by Ctrl-C. Resume with the same command and --out results/x."
    )
    from sdt_framework.errors import UserInterruptError

    inject(monkeypatch, UserInterruptError("stopped; resume with: sdt benchmark --out r"))
    status, _, err = run_main(monkeypatch, capsys, "sensors", "list")
    assert status == 130
    assert err.strip() == "interrupted: stopped; resume with: sdt benchmark --out r"


def test_sensor_file_that_is_a_folder_says_what_to_do(tmp_path, monkeypatch, capsys):
    status, _, err = run_main(
        monkeypatch, capsys, "--sensor-file", str(tmp_path), "sensors", "list"
    )
    assert status == 2
    line = one_error_line(err)
    assert str(tmp_path) in line and "Is a directory" in line and "TOML file" in line


def test_sensor_file_not_utf8_says_what_to_do(tmp_path, monkeypatch, capsys):
    profile = tmp_path / "bad.toml"
    profile.write_bytes(b'name = "x"\ndescr = "\xff\xfe"\n')
    status, _, err = run_main(monkeypatch, capsys, "--sensor-file", str(profile), "sensors", "list")
    assert status == 2
    line = one_error_line(err)
    assert line == (
        f"error: {profile}: not UTF-8 text (byte 20 = 0xff, line 2, column 10); "
        f"save it as a UTF-8 TOML file"
    )
