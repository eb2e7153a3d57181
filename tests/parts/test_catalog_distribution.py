"""The catalogue is a separate distribution, found only through its entry point.

With its entry point present every part is in ``sdt sensors list`` and
``sdt plugins list``; with the distribution's entry points gone (as after
``pip uninstall``) the parts are gone too, although the module stays
importable: nothing finds it by import path. Installing a copy of the folder
with pip ships every part file and the entry point.
"""

from __future__ import annotations

import importlib.metadata as md
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from sdt_framework import build_registry, discovery
from sdt_framework.cli.main import app
from sdt_framework.errors import UnknownNameError

pytestmark = pytest.mark.catalog
sdt_sensors_catalog = pytest.importorskip(
    "sdt_sensors_catalog", reason="install plugins/sensors-catalog (make does)"
)

FOLDER = Path(__file__).resolve().parents[2] / "plugins" / "sensors-catalog"
DIST = "sdt-sensors-catalog"
PART_FILES = sorted(p.stem for p in (FOLDER / "sdt_sensors_catalog" / "parts").glob("*.toml"))


def cli_json(*args: str) -> list[dict]:
    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


@pytest.fixture
def uninstalled(monkeypatch):
    """Entry points as if the catalogue distribution were not installed."""
    real = discovery._entry_points

    def without() -> list[tuple[md.EntryPoint, str, str]]:
        return [found for found in real() if found[1] != DIST]

    monkeypatch.setattr(discovery, "_entry_points", without)


def test_installed_parts_come_from_the_entry_point_of_their_distribution():
    registry = build_registry()
    parts = {p.name: p for p in registry.parts()}
    assert sorted(parts) == PART_FILES
    assert {(p.plugin, p.distribution) for p in parts.values()} == {("sensors-catalog", DIST)}
    listed = {s["name"]: s for s in cli_json("sensors", "list")}
    assert set(PART_FILES) <= set(listed)
    plugins = {p["name"]: p for p in cli_json("plugins", "list")}
    assert plugins["sensors-catalog"]["distribution"] == DIST
    assert sorted(plugins["sensors-catalog"]["provides"]["part"]) == PART_FILES


def test_without_the_distribution_the_parts_are_gone(uninstalled):
    registry = build_registry()
    assert registry.parts() == []
    with pytest.raises(UnknownNameError, match="unknown sensor 'adxl355'"):
        registry.sensor("adxl355")
    assert not set(PART_FILES) & {s["name"] for s in cli_json("sensors", "list")}
    assert "sensors-catalog" not in {p["name"] for p in cli_json("plugins", "list")}
    # the paper's profiles are untouched
    assert {"adxl345", "adxl357", "wilcoxon-786b10"} <= {s.name for s in registry.sensors()}


def test_an_importable_module_alone_registers_nothing():
    assert sdt_sensors_catalog.load_parts()  # importable and readable...
    assert build_registry(entry_points=False).parts() == []  # ...but only entry points count


def test_pip_install_ships_every_part_file_and_the_entry_point(tmp_path):
    source = tmp_path / "src"
    shutil.copytree(FOLDER, source, ignore=shutil.ignore_patterns("*.egg-info", "__pycache__"))
    target = tmp_path / "site"
    subprocess.run(
        [sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--no-build-isolation",
         "--target", str(target), str(source)],
        check=True, capture_output=True, text=True,
    )  # fmt: skip
    [dist] = md.distributions(path=[str(target)])
    assert dist.metadata["Name"] == DIST
    [ep] = [ep for ep in dist.entry_points if ep.group == "sdt_framework"]
    assert (ep.name, ep.value) == ("sensors-catalog", "sdt_sensors_catalog")
    shipped = sorted(p.stem for p in (target / "sdt_sensors_catalog" / "parts").glob("*.toml"))
    assert shipped == PART_FILES
