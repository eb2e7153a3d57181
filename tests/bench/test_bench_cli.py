"""`sdt benchmark` from the command line: config file + options, outputs, user errors."""

from __future__ import annotations

import subprocess
import sys

import pandas as pd
from typer.testing import CliRunner

from sdt_framework.cli.main import app

CONFIG = """
[benchmark]
dataset_options = { duration = 1.5 }
machines = ["Motor-2"]
channels = ["ch1"]
classifiers = ["lr"]
repeats = 1
"""


def test_config_file_and_options(tmp_path):
    config = tmp_path / "small.toml"
    config.write_text(CONFIG)
    out = tmp_path / "out"
    result = CliRunner().invoke(
        app,
        [
            "benchmark",
            str(config),
            "--sensors",
            "wilcoxon-786b10,adxl357",
            "--scenarios",
            "forward,interpolation",
            "--out",
            str(out),
            "--jobs",
            "1",
            "--cache-dir",
            str(tmp_path / "cache"),
            "--no-report",
        ],
        env={"COLUMNS": "120"},
    )
    assert result.exit_code == 0, result.output
    assert f"results in {out}" in result.stdout
    assert "Macro F1 (mean ± SD), Motor-2" in result.stdout
    results = pd.read_csv(out / "results.csv")
    assert set(results["scenario"]) == {"forward", "interpolation"}
    assert set(results["sensor"]) == {"wilcoxon-786b10", "adxl357"}
    assert (results["status"] == "ok").all() and len(results) == 4
    resolved = (out / "config.toml").read_text()
    assert 'sensors = [\n    "wilcoxon-786b10",\n    "adxl357",\n]' in resolved


def run_sdt(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sdt_framework", "benchmark", *args],
        capture_output=True,
        text=True,
        check=False,
    )


def test_bad_configuration_is_one_line_before_any_work(sdt_in_process, tmp_path):
    for args, message in [
        (["--sensors", "adxl999"], "error: unknown sensor 'adxl999'"),
        (["--repeats", "-3"], "error: command line: field 'repeats': Input should be greater"),
        (
            ["--scenarios", "sideways"],
            "error: command line: field 'scenarios.0': Input should be 'forward'",
        ),
    ]:
        out = tmp_path / "never"
        result = sdt_in_process("benchmark", *args, "--out", str(out))  # refused before any work
        assert result.returncode == 2, result.stderr
        assert "Traceback" not in result.stderr
        assert result.stderr.strip().startswith(message), result.stderr
        assert not out.exists()


def test_unknown_config_key(tmp_path):
    config = tmp_path / "typo.toml"
    config.write_text("[benchmark]\nrepeat = 3\n")
    result = run_sdt(str(config))
    assert result.returncode == 2
    assert f"{config}: field 'repeat': unknown option" in result.stderr
