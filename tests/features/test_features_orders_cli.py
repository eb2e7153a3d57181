"""`sdt features extract --set orders`: the speed given or estimated, and bad input as one line."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from click.testing import Result
from sdt_plugins.datasets.pump_rig import RIG_FILE
from sdt_plugins.features import orders, paper8
from sdt_plugins.readers import npy as npy_reader
from typer.testing import CliRunner

from sdt_framework import SDTError, build_registry
from sdt_framework.cli.main import app, main
from sdt_framework.features import read_feature_table

FS = 3200.0
RPM = 1480.0


@pytest.fixture(scope="module")
def signal(tmp_path_factory) -> Path:
    """4 s: 0.2 g at 1x and 0.3 g at 2x of 1480 rpm, a little noise."""
    t = np.arange(int(4 * FS)) / FS
    f = RPM / 60
    noise = 0.01 * np.random.default_rng(1).normal(size=t.size)
    x = 0.2 * np.sin(2 * np.pi * f * t) + 0.3 * np.sin(2 * np.pi * 2 * f * t) + noise
    path = tmp_path_factory.mktemp("orders") / "line.npy"
    np.save(path, x)
    return path


def invoke(*args: str) -> Result:
    reg = build_registry(entry_points=False, plugins=[paper8, orders, npy_reader], environ={})
    return CliRunner().invoke(app, list(args), obj={"registry": reg})


def _extract(signal: Path, out: Path, *options: str) -> Result:
    return invoke("features", "extract", str(signal), "--fs", "3200", "--set", "orders",
                  "--out", str(out), *options)  # fmt: skip


def _one_line_error(result: Result) -> str:
    """The SDTError the command raised (``sdt`` prints it as one line, exit 2)."""
    assert isinstance(result.exception, SDTError), result.output
    message = str(result.exception)
    assert "\n" not in message
    return message


def test_a_given_speed_is_used_and_recorded(signal: Path, tmp_path: Path) -> None:
    out = tmp_path / "o.parquet"
    result = _extract(signal, out, "--speed-rpm", "1480")
    assert result.exit_code == 0, result.output
    assert "speed: 1480 rpm (24.67 Hz; given: --speed-rpm)" in result.stdout
    table = read_feature_table(out)
    assert table.speed == "1480 rpm (24.67 Hz; given: --speed-rpm)"
    got = dict(zip(table.names, np.median(table.values, axis=0), strict=True))
    assert got["A_1X"] == pytest.approx(0.2 / np.sqrt(2), rel=5e-3)
    assert got["A_2X"] == pytest.approx(0.3 / np.sqrt(2), rel=5e-3)


def test_an_estimated_speed_is_named_an_estimate(signal: Path, tmp_path: Path) -> None:
    out = tmp_path / "o.csv"
    result = _extract(signal, out, "--nominal-rpm", "1450")  # the line is 2 % above
    assert result.exit_code == 0, result.output
    assert "speed: 1480 rpm (24.67 Hz; estimate: 1480 rpm" in result.stdout
    assert "read off the spectrum, confidence high" in result.stdout


def test_the_machine_files_shaft_speed_is_the_nominal_one(signal: Path, tmp_path: Path) -> None:
    out = tmp_path / "o.csv"
    result = _extract(signal, out, "--machines", str(RIG_FILE), "--machine", "Motor-2")
    assert result.exit_code == 0, result.output
    assert "estimate: 1480 rpm" in result.stdout


def test_no_speed_and_none_to_estimate_is_one_line(signal: Path, tmp_path: Path) -> None:
    line = _one_line_error(_extract(signal, tmp_path / "o.csv"))
    assert "feature set 'orders' works in orders of the running speed" in line
    assert "--speed-rpm RPM" in line and "--nominal-rpm RPM" in line
    assert not (tmp_path / "o.csv").exists()


def test_a_spectrum_without_a_shaft_line_near_nominal_is_one_line(signal, tmp_path) -> None:
    line = _one_line_error(_extract(signal, tmp_path / "o.csv", "--nominal-rpm", "900"))
    assert "no running speed to read off the spectrum near 900 rpm" in line
    assert "give --speed-rpm RPM" in line


def test_an_order_band_above_the_rates_nyquist_is_one_line(signal, tmp_path) -> None:
    result = invoke("features", "extract", str(signal), "--fs", "1600", "--set", "orders",
                    "--speed-rpm", "1480", "--out", str(tmp_path / "o.csv"))  # fmt: skip
    line = _one_line_error(result)
    assert "order band '0.4-40 orders'" in line and "1480 rpm" in line
    assert "above the Nyquist frequency 800 Hz of fs=1600 Hz" in line


@pytest.mark.parametrize(
    ("options", "expected"),
    [
        (["--speed-rpm", "0"], "--speed-rpm 0: give the shaft speed in rpm, above 0"),
        (["--nominal-rpm", "nan"], "--nominal-rpm nan: give the shaft speed in rpm, above 0"),
        (["--machine", "Motor-2"], "--machine Motor-2: give the machine file it is in"),
        (["--machines", str(RIG_FILE), "--machine", "Motor-9"], "has no machine 'Motor-9'"),
    ],
)
def test_bad_speed_options_are_one_line(signal, tmp_path, options, expected) -> None:
    assert expected in _one_line_error(_extract(signal, tmp_path / "o.csv", *options))


def test_sdt_prints_an_order_band_above_nyquist_as_one_line_and_exits_2(
    signal: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys
) -> None:
    monkeypatch.setenv("SDT_PLUGINS", "orders,reader-npy")
    out = str(tmp_path / "o.csv")
    argv = ["sdt", "features", "extract", str(signal), "--fs", "1600", "--set", "orders",
            "--speed-rpm", "1480", "--out", out]  # fmt: skip
    monkeypatch.setattr(sys, "argv", argv)
    with pytest.raises(SystemExit) as info:
        main()
    assert info.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {signal}: feature set 'orders': order band")
