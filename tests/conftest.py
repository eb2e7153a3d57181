"""Shared fixtures: fake installed distributions, the built-in profiles, the catalogue marker.

A test that needs the sensor catalogue (``plugins/sensors-catalog``, its own
distribution, installed by ``make``) is marked ``@pytest.mark.catalog`` (a
whole module: ``pytestmark = pytest.mark.catalog``); it is skipped, saying
why, when the catalogue is not installed. ``pytest -m "not catalog"`` runs the
rest.

Every test sees the same terminal, whoever runs the suite (a terminal of any
width, CI, a pytest-xdist worker, a shell that exports ``COLUMNS``): 80
columns, what a pipe gets, unless the test names another width for its own
command (``CliRunner().invoke(..., env={"COLUMNS": ...})`` or a child's
environment). rich reads ``COLUMNS`` once when a console is built and then keeps
it, so the ``sdt`` consoles must be built with no ``COLUMNS`` set (they then read
it at each print): ``pytest_configure`` removes it and then imports the command line,
and a session fixture sets 80 for the tests.

Following flake8's approach, a test that needs a third-party plugin writes a
module and a ``*.dist-info`` folder with ``entry_points.txt`` into a temporary
directory on ``sys.path``; importlib.metadata then finds it exactly as it would
find a pip-installed distribution.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import subprocess
import sys
import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from joblib.externals.loky import get_reusable_executor
from sdt_plugins.sensors import adxl345 as builtin_adxl345
from sdt_plugins.sensors import adxl357 as builtin_adxl357
from sdt_plugins.sensors import wilcoxon_786b10 as builtin_reference

from sdt_framework import build_registry
from sdt_framework.specs import SensorSpec

from .helpers import sdt_here

FakeDist = Callable[..., Path]
CATALOG_MISSING = "the sensor catalogue is not installed: pip install -e plugins/sensors-catalog"


def pytest_configure(config: pytest.Config) -> None:
    assert "sdt_framework.cli.common" not in sys.modules, "conftest must not import the CLI"
    os.environ.pop("COLUMNS", None)
    os.environ.pop("LINES", None)
    # build sdt's consoles now, with no COLUMNS set, so that they follow it at each print;
    # built later (a test file that imports the CLI only inside a test) they would keep 80
    importlib.import_module("sdt_framework.cli.common")
    _one_blas_thread()
    config.addinivalue_line(
        "markers", "catalog: needs the separately installed sensor catalogue (sdt_sensors_catalog)"
    )
    config.addinivalue_line(
        "markers", "in_process: the reliability tests' sdt runs in this process (sdt_in_process)"
    )


def _one_blas_thread() -> None:
    """One BLAS and one OpenMP thread here and in the commands it starts, unless the user set one.

    The suite runs one pytest-xdist worker per core (``make test``); each worker's
    OpenBLAS would start a thread per core as well, and on small matrices those
    threads spin against the other worker's: SALib's delta analysis (a Gaussian KDE
    per bootstrap sample) took 14.6 s with two threads on the loaded 2-core machine
    and 1.4 s with one. OpenMP (scikit-learn's and XGBoost's libgomp, loaded later,
    which reads ``OMP_NUM_THREADS`` when it starts) spins the same way: the
    conformance check's XGBoost fit took 9.2 s with two threads in the loaded suite
    and 0.05 s alone. A result can differ from a multi-thread run's in rounding only.
    """
    from threadpoolctl import threadpool_limits

    for name in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS"):
        os.environ.setdefault(name, "1")
    threadpool_limits(limits=int(os.environ["OPENBLAS_NUM_THREADS"]), user_api="blas")


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Skip, with the reason, every test marked ``catalog`` when the catalogue is absent."""
    if importlib.util.find_spec("sdt_sensors_catalog") is not None:
        return
    skip = pytest.mark.skip(reason=CATALOG_MISSING)
    for item in items:
        if item.get_closest_marker("catalog") is not None:
            item.add_marker(skip)


@pytest.fixture(scope="session", autouse=True)
def _terminal_of_80_columns() -> Iterator[None]:
    """``COLUMNS=80`` for every test and the commands it starts (see the module's docstring)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("COLUMNS", "80")
        yield


@pytest.fixture
def fake_dist(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[FakeDist]:
    """Factory: ``fake_dist("dist-name", {"ep-name": "module"}, {"module": "source"})``."""
    root = tmp_path / "site"
    root.mkdir()
    monkeypatch.syspath_prepend(str(root))
    added: list[str] = []

    def make(dist: str, entry_points: dict[str, str], modules: dict[str, str]) -> Path:
        for module, source in modules.items():
            (root / f"{module}.py").write_text(textwrap.dedent(source))
            added.append(module)
        info = root / f"{dist.replace('-', '_')}-1.2.3.dist-info"
        info.mkdir()
        (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {dist}\nVersion: 1.2.3\n")
        lines = "\n".join(f"{name} = {target}" for name, target in entry_points.items())
        (info / "entry_points.txt").write_text(f"[sdt_framework]\n{lines}\n")
        importlib.invalidate_caches()
        # joblib keeps one loky pool per process; workers an earlier test started do not
        # see this new site (as a running sdt would not), so the next pool starts afresh
        get_reusable_executor().shutdown(wait=True)
        return root

    yield make
    for module in added:
        sys.modules.pop(module, None)


@pytest.fixture
def sdt_in_process(tmp_path):
    """``sdt(*args, env=...)`` as the reliability tests' ``sdt`` fixture gives it (a
    ``CompletedProcess``: exit status, stdout, stderr; the cache in the test's folder), but
    in this process (:func:`~tests.helpers.sdt_here`: Python's warnings on its stderr, as a
    child prints them): for commands that end before any worker starts (a bad input refused,
    a file inspected or checked), where a real process adds two seconds of imports and
    checks nothing more. Signals, memory caps, orphans and workers keep ``run_sdt``."""

    def run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
        return sdt_here(*args, env={"SDT_CACHE_DIR": str(tmp_path / "cache"), **(env or {})})

    return run


@pytest.fixture(scope="session")
def registry():
    """The installed registry (built-in plugins), shared: a test that adds specs builds its own."""
    return build_registry()


@pytest.fixture(scope="session")
def readers(registry):
    """The built-in signal readers, as a command hands them down (``registry.signal_readers()``)."""
    return registry.signal_readers()


def _sdt_main(*args: str) -> tuple[int, str, str]:
    done = sdt_here(*args)
    return done.returncode, done.stdout, done.stderr


@pytest.fixture
def sdt_main():
    """``sdt_main(*args)``: ``sdt`` in this process (:func:`~tests.helpers.sdt_here`, in the
    environment the test set): (exit status, stdout, stderr)."""
    return _sdt_main


#: the built-in profiles of paper Table 1, as their plugins register them (not copies that
#: could drift), from a registry of those plugins alone (no entry points, no SDT_* switches)
_BUILTIN = build_registry(
    entry_points=False,
    plugins=[builtin_adxl345, builtin_adxl357, builtin_reference],
)
ADXL345 = _BUILTIN.sensor("adxl345")
ADXL357 = _BUILTIN.sensor("adxl357")
REFERENCE = _BUILTIN.sensor("wilcoxon-786b10")


@pytest.fixture
def adxl345() -> SensorSpec:
    """The ADXL345 profile of paper Table 1."""
    return ADXL345


@pytest.fixture
def adxl357() -> SensorSpec:
    """The ADXL357 profile of paper Table 1."""
    return ADXL357


@pytest.fixture
def reference() -> SensorSpec:
    """The reference Wilcoxon chain of paper Table 1."""
    return REFERENCE


@pytest.fixture(params=[ADXL345, ADXL357], ids=lambda s: s.name)
def mems(request: pytest.FixtureRequest) -> SensorSpec:
    """Each MEMS profile of paper Table 1."""
    return request.param
