"""The README's plugin, packaged exactly as the README shows, loads through its entry point.

The entry point names the class (``my_package.plugin:MyPlugin``); before the fix
discovery registered the class itself and the hooks were called without ``self``
(status ``error``), while ``check_plugin(MyPlugin())`` passed. The package is built
from the README's own blocks and pip-installed into a temporary target folder.
"""

from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.conformance import ConformanceError, check_plugin

from ..helpers import run_sdt

README = Path(__file__).resolve().parents[2] / "README.md"


def _block(marker: str, lang: str) -> str:
    match = re.search(rf"<!-- {marker} -->\n```{lang}\n(.*?)```", README.read_text(), re.S)
    assert match, f"README lost its {marker} block"
    return match.group(1)


@pytest.fixture(scope="module")
def package(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """my-package/ as the README lays it out: pyproject.toml, my_package/{__init__,plugin}.py."""
    root = tmp_path_factory.mktemp("src") / "my-package"
    (root / "my_package").mkdir(parents=True)
    (root / "my_package" / "__init__.py").write_text("")
    (root / "my_package" / "plugin.py").write_text(_block("readme-plugin-example", "python"))
    (root / "pyproject.toml").write_text(_block("readme-plugin-pyproject", "toml"))
    return root


@pytest.fixture(scope="module")
def site(package: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """``pip install ./my-package`` into a target folder (no network: no deps, no isolation)."""
    target = tmp_path_factory.mktemp("site")
    pip = [sys.executable, "-m", "pip", "install", "--quiet", "--no-deps"]
    subprocess.run(
        [*pip, "--no-build-isolation", "--target", str(target), str(package)],
        check=True,
        capture_output=True,
        text=True,
    )
    return target


def _sdt(*args: str, site: Path, tmp: Path) -> subprocess.CompletedProcess[str]:
    return run_sdt(
        *args,
        cwd=tmp,
        env={"PYTHONPATH": str(site), "SDT_CACHE_DIR": str(tmp / "cache")},
        without={"SDT_PLUGINS", "SDT_BLOCK_PLUGINS"},
    )


def test_the_plugin_file_runs_as_a_script(package):
    """``python my_package/plugin.py`` runs the conformance checks on the class and prints."""
    run = subprocess.run(
        [sys.executable, "my_package/plugin.py"], cwd=package, capture_output=True, text=True
    )
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "0.00390625 {'max_depth': 6}"  # 2 * 8 g / 2**12


def test_installed_class_entry_point_loads(site, tmp_path):
    run = _sdt("plugins", "list", "--json", site=site, tmp=tmp_path)
    assert run.returncode == 0, run.stderr
    plugins = {p["name"]: p for p in json.loads(run.stdout)}
    mine = plugins["my-plugin"]
    assert (mine["status"], mine["error"]) == ("loaded", "")
    assert mine["distribution"] == "my-package"
    assert mine["provides"] == {"sensor": ["my-mems"], "classifier": ["tree"]}


def test_installed_plugin_sensor_degrades_through_the_cli(site, tmp_path):
    """``sdt degrade --sensor my-mems``: 2 s at 20 kHz -> 3200 samples at 1600 Hz, 12-bit grid."""
    t = np.arange(40000) / 20000.0
    np.save(tmp_path / "tone.npy", 0.5 * np.sin(2 * np.pi * 80.0 * t))
    run = _sdt(
        "degrade", "tone.npy", "--sensor", "my-mems", "--fs", "20000", "--out", "y.npy",
        site=site, tmp=tmp_path,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    y = np.load(tmp_path / "y.npy")
    assert y.shape == (3200,)
    step = 2 * 8 / 2**12
    assert np.allclose(y / step, np.round(y / step))
    assert 0.4 < np.sqrt(2) * np.std(y) < 0.6  # the 80 Hz tone passes the 400 Hz filter


def test_check_plugin_accepts_the_three_forms_and_the_entry_point_value(site, monkeypatch):
    monkeypatch.syspath_prepend(str(site))
    from my_package import plugin  # type: ignore[import-not-found]

    names = {("sensor", "my-mems"), ("classifier", "tree")}
    for form in (plugin.MyPlugin, plugin.MyPlugin(), "my_package.plugin:MyPlugin"):
        assert {(s.kind, s.name) for s in check_plugin(form)} == names


def test_a_class_that_needs_arguments_is_refused_with_a_reason():
    from sdt_framework import hookimpl

    class NeedsArgs:
        def __init__(self, gain: float) -> None:
            self.gain = gain

        @hookimpl
        def register_sensors(self, register):  # pragma: no cover - never called
            raise AssertionError

    with pytest.raises(ConformanceError, match="cannot be instantiated without arguments"):
        check_plugin(NeedsArgs)
    with pytest.raises(ConformanceError, match="entry point 'no_such_pkg:X' failed to load"):
        check_plugin("no_such_pkg:X")
