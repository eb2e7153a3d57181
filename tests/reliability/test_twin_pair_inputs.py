"""Bad pair inputs to ``sdt twin check`` and ``sdt twin fit`` (issue 29: B4, B5, B6 and the
weak pair rows): each is one ``error:`` line (exit 2), and fit refuses what check refuses.

The pair is synthetic and small: a reference of 4 s at 20 kHz on axis x (tones of
1 g at 80, 160, 315 and 630 Hz over a 1 ug noise) and a device made from it by the
adxl345 twin clocked at 3134 Hz, written as a CSV with a time column in seconds
(and as an NPY with its ``rate_hz``). The pair checks cleanly as written; each
test changes one thing a user could get wrong.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.api import degrade
from sdt_framework.twin.align import at_rate

FS_REF = 20_000.0
RATE = 3134.0
DATA = Path(__file__).parents[1] / "data" / "endaq"


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


PAIR = """[reference]
file = "ref.npy"
axes = ["x"]
rate_hz = 20000.0
part = "piezo"

[device]
file = "dev.csv"
columns = ["ax"]
time_column = "t"
axes = ["x"]
part = "ADXL345"
"""


@pytest.fixture(scope="module")
def signals(registry) -> tuple[np.ndarray, np.ndarray]:
    t = np.arange(int(4 * FS_REF)) / FS_REF
    reference = 1e-6 * np.random.default_rng(3).normal(size=t.size)
    for f in (80, 160, 315, 630):
        reference += np.sin(2 * np.pi * f * t)
    device, _ = degrade(reference, FS_REF, at_rate(registry.sensor("adxl345"), RATE), seed=7)
    return reference, device


def _write(folder: Path, signals, *, pair: str = PAIR, times=None, device_scale=1.0) -> Path:
    reference, device = signals
    np.save(folder / "ref.npy", reference)
    np.save(folder / "dev.npy", device * device_scale)
    t = np.arange(device.size) / RATE if times is None else times
    table = np.column_stack([t, device * device_scale])
    np.savetxt(folder / "dev.csv", table, delimiter=",", header="t,ax", comments="",
               fmt="%.12g")  # fmt: skip
    (folder / "pair.toml").write_text(pair, encoding="utf-8")
    return folder / "pair.toml"


def _one_error(run) -> str:
    assert run.returncode == 2, (run.stdout, run.stderr)
    assert run.stderr.startswith("error:") and run.stderr.count("\n") == 1, run.stderr
    return run.stderr


def _fit(sdt, pair: Path, *more: str):
    return sdt("twin", "fit", str(pair), "--sensor", "adxl345", "--out",
               str(pair.parent / "fitted.toml"), *more)  # fmt: skip


def test_the_pair_as_written_checks(sdt, tmp_path, signals):
    run = sdt("twin", "check", str(_write(tmp_path, signals)), "--sensor", "adxl345")
    assert run.returncode == 0, run.stderr
    assert "judgeable bands" in run.stdout


def test_a_repeated_axis_is_refused_on_the_command_line(sdt):
    run = sdt("twin", "check", str(DATA / "SSX_Data.IDE"), "--sensor", "adxl345", "--axes",
              "x,y,z,x")  # fmt: skip
    assert "name axis 'x' twice" in _one_error(run)


@pytest.mark.parametrize("command", ["check", "fit"])
def test_a_sensor_without_a_clock_is_refused_not_a_traceback(sdt, tmp_path, command):
    extra = ["--out", str(tmp_path / "f.toml")] if command == "fit" else []
    run = sdt("twin", command, str(DATA / "SSX_Data.IDE"), "--sensor", "native-reference",
              "--device-channel", "32", *extra)  # fmt: skip
    assert "native-reference: samples at the recording's own rate" in _one_error(run)


@pytest.mark.parametrize("command", ["check", "fit"])
@pytest.mark.parametrize(
    ("edit", "words"),
    [
        (('part = "ADXL345"', 'part = "ADXL345"\nstart_s = nan'), "field 'device.start_s'"),
        (('file = "dev.csv"\ncolumns = ["ax"]\ntime_column = "t"',
          'file = "dev.npy"\nrate_hz = 1e-300'), "samples at 1e-300 Hz"),
        (("rate_hz = 20000.0", "rate_hz = 20000000.0"), "differ 1000-fold in length"),
    ],
    ids=["start-nan", "rate-1e-300", "rate-in-khz"],
)  # fmt: skip
def test_check_and_fit_refuse_the_same_bad_pair(sdt, tmp_path, signals, command, edit, words):
    pair = _write(tmp_path, signals, pair=PAIR.replace(*edit))
    run = sdt("twin", "check", str(pair), "--sensor", "adxl345") if command == "check" else \
        _fit(sdt, pair)  # fmt: skip
    assert words in _one_error(run)
    assert not (tmp_path / "fitted.toml").exists()


@pytest.mark.parametrize("command", ["check", "fit"])
def test_a_time_column_in_milliseconds_is_named_as_a_rate_mismatch(sdt, tmp_path, signals, command):
    times = 1e3 * np.arange(signals[1].size) / RATE  # ms, where seconds are expected
    pair = _write(tmp_path, signals, times=times)
    run = sdt("twin", "check", str(pair), "--sensor", "adxl345") if command == "check" else \
        _fit(sdt, pair)  # fmt: skip
    err = _one_error(run)
    # 4 s of reference against 4000 s of device: the time column is 1000 times too slow
    assert "differ 1000-fold in length" in err and "time column in ms" in err


def test_a_huge_rate_is_printed_in_a_few_digits(sdt, tmp_path, signals):
    pair = _write(tmp_path, signals, pair=PAIR.replace("rate_hz = 20000.0", "rate_hz = 1e308"))
    err = _one_error(sdt("twin", "check", str(pair), "--sensor", "adxl345"))
    assert "1e+308 Hz" in err and not re.search(r"\d{20}", err)


@pytest.mark.parametrize(
    ("columns", "words"),
    [('["ax", "ax"]', "columns name 'ax' twice"), ('["t"]', "time_column 't' is also among")],
)
def test_a_column_named_twice_or_the_time_column_as_an_axis_is_refused(
    sdt, tmp_path, signals, columns, words
):
    text = PAIR.replace('columns = ["ax"]', f"columns = {columns}")
    if columns.count('"ax"') == 2:
        text = text.replace('axes = ["x"]\npart = "ADXL345"', 'axes = ["x", "y"]\npart = "ADXL345"')
    pair = _write(tmp_path, signals, pair=text)
    assert words in _one_error(sdt("twin", "check", str(pair), "--sensor", "adxl345"))


def test_a_100_kb_part_name_is_not_echoed_whole(sdt, tmp_path, signals):
    pair = _write(tmp_path, signals, pair=PAIR.replace('"piezo"', '"' + "P" * 100_000 + '"'))
    run = sdt("twin", "check", str(pair), "--sensor", "adxl345")
    assert run.returncode == 0, run.stderr
    assert "P" * 50 in run.stdout and "P" * 61 not in run.stdout
    assert len(run.stdout) < 20_000


def test_a_two_second_gap_in_a_time_column_is_refused_naming_it(sdt, tmp_path, signals):
    times = np.arange(signals[1].size) / RATE
    times[5000:] += 2.0  # the recorder stopped for 2 s after sample 4999
    pair = _write(tmp_path, signals, times=times)
    err = _one_error(sdt("twin", "check", str(pair), "--sensor", "adxl345"))
    assert "dev.csv [device]: timestamps jump by 2 s" in err
    assert "between samples 4,999 and 5,000" in err


@pytest.mark.parametrize(
    ("name", "words"),
    [
        ('my"fit', "a profile name is lower-case letters"),
        ("fit[odr=1]", "a profile name is lower-case letters"),
        ("\x1b[2Jfit", "a profile name is lower-case letters"),
        ("adxl345", "a sensor of that name is already known"),
    ],
)
def test_fit_refuses_a_name_that_cannot_be_loaded_back(sdt, tmp_path, name, words):
    run = sdt("twin", "fit", str(DATA / "SSX_Data.IDE"), "--sensor", "adxl345", "--out",
              str(tmp_path / "f.toml"), "--name", name)  # fmt: skip
    assert words in _one_error(run)
    assert not (tmp_path / "f.toml").exists()


def test_fit_refuses_a_device_in_mg_declared_as_g(sdt, tmp_path, signals):
    pair = _write(tmp_path, signals, device_scale=1000.0)  # mg values, units = "g" (default)
    err = _one_error(_fit(sdt, pair))
    assert "the device's values look in mg, declared as g" in err
    assert not (tmp_path / "fitted.toml").exists()


def test_a_full_disk_while_writing_the_fitted_profile_says_so(
    sdt_main, monkeypatch, tmp_path, signals
):
    import errno

    def full(self, data):
        raise OSError(errno.ENOSPC, "No space left on device")

    pair = _write(tmp_path, signals)
    monkeypatch.setattr(Path, "write_bytes", full)
    code, _, err = sdt_main("twin", "fit", str(pair), "--sensor", "adxl345", "--out",
                            str(tmp_path / "fitted.toml"))  # fmt: skip
    assert code == 2 and err.startswith("error:") and err.count("\n") == 1, err
    assert "fitted.toml: no space left on device; the disk is full" in err
    assert "outputerror" not in err
    assert not (tmp_path / "fitted.toml").exists()
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_dataset_inspect_of_a_pair_file_points_to_twin_check(sdt, tmp_path, signals):
    pair = _write(tmp_path, signals)
    assert "sdt twin check" in _one_error(sdt("dataset", "inspect", str(pair)))


@pytest.mark.parametrize(
    ("path", "words"),
    [("/dev/zero", "not a regular file (a character device)"), ("dir.toml", "Is a directory")],
)
def test_a_pair_path_that_is_not_a_file_says_what_it_is(sdt, tmp_path, path, words):
    (tmp_path / "dir.toml").mkdir()
    run = sdt("twin", "check", path if path.startswith("/") else str(tmp_path / path),
              "--sensor", "adxl345")  # fmt: skip
    assert words in _one_error(run)
