"""The example third-party plugin is found only through its entry point, once installed."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from sdt_framework.conformance import check_plugin

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "sdt-adxl355"


def sdt_json(*args: str, pythonpath: str | None) -> list[dict]:
    env = {k: v for k, v in os.environ.items() if k not in {"PYTHONPATH", "SDT_PLUGINS"}}
    if pythonpath:
        env["PYTHONPATH"] = pythonpath
    result = subprocess.run(
        [sys.executable, "-m", "sdt_framework", *args, "--json"],
        capture_output=True,
        text=True,
        env=env,
        check=True,
    )
    return json.loads(result.stdout)


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """pip-install the example into a temporary target folder (no network needed)."""
    target = tmp_path_factory.mktemp("site")
    source = tmp_path_factory.mktemp("src") / EXAMPLE.name
    shutil.copytree(EXAMPLE, source)  # building in place would leave metadata in the repo
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "install",
            "--quiet",
            "--no-deps",
            "--no-build-isolation",
            "--target",
            str(target),
            str(source),
        ],
        check=True,
        capture_output=True,
        text=True,
    )
    return target


@pytest.mark.catalog
def test_installed_example_appears_in_sensors_and_plugins(installed):
    sensors = {s["name"]: s for s in sdt_json("sensors", "list", pythonpath=str(installed))}
    assert sensors["adxl355-example"]["distribution"] == "sdt-adxl355"
    assert sensors["adxl355-example"]["full_scale_g"] == 8
    plugins = {p["name"]: p for p in sdt_json("plugins", "list", pythonpath=str(installed))}
    assert plugins["adxl355-example"]["distribution"] == "sdt-adxl355"
    assert plugins["adxl355-example"]["version"] == "0.1.0"
    assert plugins["adxl355-example"]["status"] == "loaded"
    # beside the catalogue's part of the same chip: different names, no conflict
    assert plugins["sensors-catalog"]["status"] == "loaded"


def test_uninstalled_example_is_gone():
    names = {s["name"] for s in sdt_json("sensors", "list", pythonpath=None)}
    assert "adxl355-example" not in names
    # Importable source alone is not enough: discovery goes only through entry points.
    names = {s["name"] for s in sdt_json("sensors", "list", pythonpath=str(EXAMPLE))}
    assert "adxl355-example" not in names


def test_example_passes_the_conformance_checks(monkeypatch):
    monkeypatch.syspath_prepend(str(EXAMPLE))
    import sdt_adxl355

    [spec] = check_plugin(sdt_adxl355)
    assert spec.name == "adxl355-example" and spec.adc_bits == 20
