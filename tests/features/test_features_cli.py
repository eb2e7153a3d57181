"""`sdt features extract`: round trips through CSV and Parquet with units, and user errors."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest
from click.testing import Result
from sdt_plugins.features import paper8
from sdt_plugins.readers import npy as npy_reader
from typer.testing import CliRunner

from sdt_framework import Registry, build_registry
from sdt_framework.api import extract
from sdt_framework.cli.main import app, main
from sdt_framework.errors import SDTError
from sdt_framework.features import feature, read_feature_table

FS = 3200.0


@feature(name="p2p", unit="g")
def p2p(windows: np.ndarray, fs: float) -> np.ndarray:
    return np.ptp(windows, axis=1)


def registry() -> Registry:
    reg = build_registry(entry_points=False, plugins=[paper8, npy_reader], environ={})
    reg.add(p2p.spec)
    return reg


@pytest.fixture
def signal(tmp_path: Path) -> tuple[Path, np.ndarray]:
    x = np.random.default_rng(5).normal(0, 0.3, size=(2, 320 + 3 * 2048 + 100)).astype(np.float32)
    path = tmp_path / "signal.npy"
    np.save(path, x)
    return path, x


def invoke(*args: str) -> Result:
    return CliRunner().invoke(app, list(args), obj={"registry": registry()})


@pytest.mark.parametrize("suffix", [".csv", ".parquet"])
def test_round_trip_keeps_values_units_and_indices(signal, tmp_path: Path, suffix: str) -> None:
    path, x = signal
    out = tmp_path / "sub" / f"features{suffix}"
    result = invoke(
        "features", "extract", str(path), "--fs", "3200", "--set", "paper8+p2p", "--out", str(out)
    )
    assert result.exit_code == 0, result.output
    assert "wrote 6 windows x 9 features (paper8+p2p" in result.stdout
    back = read_feature_table(out)
    expected = extract(x, FS, registry().feature_set("paper8"))
    np.testing.assert_array_equal(back.values[:, :8], expected.values)  # float32 exact
    assert back.values.dtype == np.float32
    assert back.names[-1] == "p2p" and back.units == (*expected.units, "g")
    np.testing.assert_array_equal(back.acquisition, [0, 0, 0, 1, 1, 1])
    np.testing.assert_array_equal(back.window, [0, 1, 2] * 2)
    assert [p.name for p in out.parent.iterdir()] == [out.name]  # no temporary left behind


def test_csv_headers_carry_units(signal, tmp_path: Path) -> None:
    out = tmp_path / "f.csv"
    assert (
        invoke("features", "extract", str(signal[0]), "--fs", "3200", "--out", str(out)).exit_code
        == 0
    )
    header = out.read_text().splitlines()[0]
    assert header == (
        "acquisition,window,sigma[g],S[1],K[1],CF[1],A_RMS[g],A_Peak[g],V_RMS[mm/s],D_RMS[um]"
    )


def test_parquet_field_and_schema_metadata(signal, tmp_path: Path) -> None:
    out = tmp_path / "f.parquet"
    assert (
        invoke(
            "features",
            "extract",
            str(signal[0]),
            "--fs",
            "3200",
            "--window-s",
            "0.32",
            "--settle-s",
            "0",
            "--out",
            str(out),
        ).exit_code
        == 0
    )
    schema = pq.read_schema(out)
    assert schema.field("V_RMS").metadata[b"unit"] == b"mm/s"
    assert str(schema.field("V_RMS").type) == "float"
    meta = json.loads(schema.metadata[b"sdt_framework.features"])
    assert meta | {"units": None} == {
        "feature_set": "paper8",
        "fs": 3200.0,
        "window_length": 1024,
        "settle": 0,
        "units": None,
    }
    assert pq.read_table(out).num_rows == 2 * 6


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--set", "papr8"], "Did you mean 'paper8'"),
        (["--out-suffix", ".txt"], "must end in .csv or .parquet"),
        (["--window-s", "30"], "too short"),
    ],
)
def test_user_errors_are_sdt_errors(signal, tmp_path: Path, args: list[str], message: str) -> None:
    suffix = args[1] if args[0] == "--out-suffix" else ".csv"
    extra = [] if args[0] == "--out-suffix" else args
    out = tmp_path / f"f{suffix}"
    result = invoke(
        "features", "extract", str(signal[0]), "--fs", "3200", "--out", str(out), *extra
    )
    assert isinstance(result.exception, SDTError) and message in str(result.exception)
    assert not out.exists()


def test_main_prints_one_line_and_exits_2(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "x.npy"
    np.save(bad, np.zeros((2, 2, 2)))
    monkeypatch.setenv("SDT_PLUGINS", "paper8,reader-npy")  # the feature set and the reader
    monkeypatch.setattr(
        sys,
        "argv",
        ["sdt", "features", "extract", str(bad), "--fs", "3200", "--out", str(tmp_path / "o.csv")],
    )
    with pytest.raises(SystemExit) as info:
        main()
    assert info.value.code == 2
    err = capsys.readouterr().err
    assert "array of shape (2, 2, 2); expected 1-D or 2-D" in err and "Traceback" not in err


def test_help_has_an_example() -> None:
    result = CliRunner().invoke(app, ["features", "extract", "--help"])
    assert result.exit_code == 0 and "sdt features extract" in result.stdout
