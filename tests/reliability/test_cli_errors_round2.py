"""Issue 24, round 2: hostile inputs that gave a traceback, or an error naming no file, now
give one line (``error: ...``, exit 2) naming the file, the field or option and the value.

Each case below failed on main at e00f86b: an OverflowError, UnicodeDecodeError,
AttributeError, ZeroDivisionError or RecursionError traceback (exit 1), or a line that did
not name the file or option. Every command is refused before any work, so the module runs
in about a second.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest


def refused(result: tuple[int, str, str]) -> str:
    """The single ``error:`` line of a command (``sdt_main``'s result) that exited 2."""
    status, _, err = result
    lines = [line for line in err.splitlines() if line.strip()]
    assert status == 2, err
    assert "Traceback" not in err
    assert len(lines) == 1, err
    assert lines[0].startswith("error: ")
    return lines[0]


def write(path: Path, content: bytes | str) -> Path:
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    return path


# --- benchmark configs -------------------------------------------------------------------


@pytest.mark.parametrize("field", ["window_s", "settle_s"])
def test_an_infinite_window_or_settling_in_a_config_names_the_field(sdt_main, tmp_path, field):
    config = write(tmp_path / "bench.toml", f"[benchmark]\n{field} = inf\n")
    line = refused(sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line == f"error: {config}: field {field!r}: Input should be a finite number (got inf)"


def test_a_window_of_1e308_seconds_in_a_config_is_refused_by_its_bound(sdt_main, tmp_path):
    # finite, but 1e308 s x 20 kHz overflows the sample count (main: OverflowError)
    config = write(tmp_path / "bench.toml", "[benchmark]\nwindow_s = 1e308\n")
    line = refused(sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line == (
        f"error: {config}: field 'window_s': Input should be less than or equal to 3600 "
        f"(got 1e+308)"
    )


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        # one Latin-1 byte: the file, the byte, its line and column, and what to do
        (b'[benchmark]\nmachines = ["Mot\xe9"]\n', "byte 28 = 0xe9, line 2, column 17"),
        (b"[benchmark]\nrepeats = 2\n\x00\n", "NUL byte (line 3)"),
        ("[benchmark]\nrepeats = 2\n".encode("utf-16"), "is UTF-16 text"),
        ("[benchmark]\nrepeats = 2\n".encode("utf-16-le"), "NUL byte (line 1)"),
    ],
    ids=["latin-1", "nul", "utf-16", "utf-16-no-bom"],
)
def test_a_config_that_is_not_utf8_is_one_line(sdt_main, tmp_path, content, needle):
    config = write(tmp_path / "bench.toml", content)
    line = refused(sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line.startswith(f"error: {config}: ") and needle in line
    assert "UTF-8" in line  # what to do: save it as UTF-8


def test_a_config_with_a_utf8_byte_order_mark_is_read(sdt_main, tmp_path):
    """Windows editors write a BOM; the file is read (its invalid field is what is named)."""
    config = write(tmp_path / "bench.toml", b"\xef\xbb\xbf[benchmark]\nrepeats = 0\n")
    line = refused(sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line.startswith(f"error: {config}: field 'repeats': Input should be greater than")


def test_a_config_too_large_to_be_one_is_refused_after_16_mb(sdt_main, tmp_path):
    # main read it whole (read_text); a device such as /dev/zero is refused unread
    # (tests/reliability/test_memory_cause.py), a huge regular file here
    config = tmp_path / "big.toml"
    with config.open("wb") as handle:
        handle.truncate(17 * 2**20)  # sparse: 17 MB of NUL bytes
    line = refused(sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line == (
        f"error: {config}: larger than 16 MB, too large for a TOML config or profile; "
        "check that this is the right file"
    )


def test_a_benchmark_key_that_is_not_a_table_names_it(sdt_main, tmp_path):
    config = write(tmp_path / "bench.toml", "benchmark = 5\n")
    line = refused(sdt_main("benchmark", str(config), "--out", str(tmp_path / "out")))
    assert line.startswith(f"error: {config}: field 'benchmark': must be a table")
    assert line.endswith("got int 5")


def test_dataset_options_that_are_not_a_table_name_the_field_under_quick(sdt_main, tmp_path):
    config = write(tmp_path / "bench.toml", '[benchmark]\ndataset_options = "abc"\n')
    args = ("benchmark", str(config), "--quick", "--out", str(tmp_path / "out"))
    line = refused(sdt_main(*args))
    assert line == (
        f"error: {config}: field 'dataset_options': Input should be a valid dictionary (got 'abc')"
    )


# --- features extract and dataset synth ---------------------------------------------------


@pytest.fixture
def signal_file(tmp_path: Path) -> Path:
    path = tmp_path / "sig.npy"
    np.save(path, np.random.default_rng(0).normal(size=8000))
    return path


@pytest.mark.parametrize(
    ("option", "value"),
    [("--settle-s", "nan"), ("--window-s", "inf"), ("--window-s", "nan"), ("--settle-s", "inf")],
)
def test_features_extract_refuses_a_non_finite_window_naming_the_option(
    sdt_main, tmp_path, signal_file, option, value
):
    args = ("features", "extract", str(signal_file), "--fs", "3200", option, value)
    line = refused(sdt_main(*args, "--out", str(tmp_path / "f.csv")))
    assert line == f"error: {option} {value}: give a finite number of seconds"


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        # 100 samples at 3200 Hz: one 0.64 s window after 0.1 s settling needs 320 + 2048
        (np.zeros(100), "acquisitions of 100 samples are too short"),
        # refused by the NPY reader as it reads the file (a manifest row's rule)
        (np.where(np.arange(8000) == 500, np.nan, 0.0), "acquisition 0, sample 500: non-finite"),
    ],
    ids=["too-short", "nan"],
)
def test_features_extract_names_the_file_of_a_bad_signal(sdt_main, tmp_path, content, needle):
    path = tmp_path / "recording.npy"
    np.save(path, content)
    args = ("features", "extract", str(path), "--fs", "3200", "--out", str(tmp_path / "f.csv"))
    line = refused(sdt_main(*args))
    assert line.startswith(f"error: {path}: ") and needle in line


@pytest.mark.parametrize("value", ["inf", "nan", "-1", "-inf"])
def test_dataset_synth_refuses_a_duration_that_is_not_finite_and_positive(
    sdt_main, tmp_path, value
):
    out = tmp_path / "synth"
    line = refused(sdt_main("dataset", "synth", "--out", str(out), f"--duration={value}"))
    assert line.startswith(f"error: --duration {float(value)}: give a finite number of seconds")
    assert not out.exists()  # refused before the folder is made


# --- sweep files --------------------------------------------------------------------------


def sweep_file(tmp_path: Path, levels: str, tie: str) -> Path:
    text = (
        f'[sweep]\nbase = "adxl345"\n[sweep.axes]\nsampling_rate_hz = {{ levels = {levels} }}\n'
        f'[sweep.ties]\ndigital_cutoff_hz = "{tie}"\n'
        f'[benchmark]\nclassifiers = ["lr"]\nrepeats = 1\nmachines = ["Motor-2"]\n'
        f"dataset_options = {{ duration = 1.5 }}\nreport = false\n"
    )
    return write(tmp_path / "sweep.toml", text)


def explore(sdt_main, tmp_path: Path, sweep: Path) -> str:
    return refused(sdt_main("explore", str(sweep), "--out", str(tmp_path / "out")))


def test_a_tie_dividing_by_a_constant_zero_is_refused_with_the_file(sdt_main, tmp_path):
    sweep = sweep_file(tmp_path, "[800, 1600]", "rate / (2 - 2)")
    line = explore(sdt_main, tmp_path, sweep)
    assert line.startswith(f"error: {sweep}: ")
    assert "tie digital_cutoff_hz = 'rate / (2 - 2)' divides by zero" in line


def test_a_tie_dividing_by_zero_at_every_point_names_the_values(sdt_main, tmp_path):
    # adxl345 has 13 bits: bits - 13 is zero at both points
    sweep = sweep_file(tmp_path, "[800, 1600]", "rate / (bits - 13)")
    line = explore(sdt_main, tmp_path, sweep)
    assert line.startswith(f"error: {sweep}: none of the 2 design points is a valid sensor")
    assert "tie 'rate / (bits - 13)' is not a finite number at rate=800, bits=13" in line


def test_a_tie_of_100000_terms_is_refused_before_it_is_parsed(sdt_main, tmp_path):
    tie = " + ".join(["rate"] * 100_000)
    line = explore(sdt_main, tmp_path, sweep_file(tmp_path, "[800, 1600]", tie))
    assert f"tie digital_cutoff_hz is {len(tie)} characters long (at most 200)" in line


@pytest.mark.parametrize("level", ["nan", "inf"])
def test_a_non_finite_sweep_level_names_the_axis(sdt_main, tmp_path, level):
    sweep = sweep_file(tmp_path, f"[{level}, 1600]", "rate / 2")
    line = explore(sdt_main, tmp_path, sweep)
    assert line == (
        f"error: {sweep}: field 'sweep.axes.sampling_rate_hz.levels.0': "
        f"Input should be a finite number"
    )


# --- sensor files -------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        ("sensor = 5\n", "field 'sensor': must be a table [sensor] or tables [[sensor]]"),
        ('name = "x"\nx = ' + "[" * 5000 + "]" * 5000 + "\n", "nests arrays or tables"),
        ('name = "x"\nx = ' + "[" * 500 + "]" * 500 + "\n", "nests arrays or tables"),
    ],
    ids=["sensor-5", "nested-5000", "nested-500"],
)
def test_a_malformed_sensor_file_is_one_line_naming_it(sdt_main, tmp_path, content, needle):
    profile = write(tmp_path / "mine.toml", content)
    line = refused(sdt_main("--sensor-file", str(profile), "sensors", "list"))
    assert line.startswith(f"error: {profile}: ") and needle in line
