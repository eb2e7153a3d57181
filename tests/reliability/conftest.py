"""Shared fixtures of the reliability tests: a small benchmark, a folder nobody may write,
and ``sdt`` run as a user runs it (a real process: exit status and stderr as printed). A test
file whose commands end before any worker starts swaps in ``sdt_in_process`` (same calls and
result, no process start; tests/conftest.py)."""

from __future__ import annotations

import os
import signal
import subprocess
from pathlib import Path
from typing import Any

import pytest

from sdt_framework.bench.config import BenchmarkConfig

from ..helpers import run_sdt

#: Motor-2 only (15 runs), 1.5 s acquisitions (2 windows per channel), 2 channels, 1 sensor.
SMALL: dict[str, Any] = {
    "dataset_options": {"duration": 1.5},
    "machines": ["Motor-2"],
    "channels": ["ch1", "ch4"],
    "sensors": ["adxl345"],
    "classifiers": ["lr", "knn"],
    "repeats": 2,
    "jobs": 1,
    "report": False,
}


@pytest.fixture(autouse=True)
def _sigint_raises_keyboard_interrupt():
    """In-process tests see SIGINT as KeyboardInterrupt, whatever the parent shell ignored.

    A shell that starts a job in the background (CI runners often do) makes it
    ignore SIGINT, and children inherit that; a Ctrl-C test would then test
    nothing. (Processes the tests start reset it themselves, see test_bench_kill.)
    """
    previous = signal.getsignal(signal.SIGINT)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


@pytest.fixture
def small_config(tmp_path):
    """Factory for a small config with its own feature cache."""

    def make(**changes: Any) -> BenchmarkConfig:
        return BenchmarkConfig(**{**SMALL, "cache_dir": str(tmp_path / "cache"), **changes})

    return make


@pytest.fixture
def read_only_dir(tmp_path) -> Path:
    """A folder this process cannot write into.

    Mode 0o555 stops an ordinary user; root ignores file modes, so for root
    the folder is one in sysfs, which nobody can create files in.
    """
    if os.geteuid() == 0:
        return Path("/sys/kernel")
    folder = tmp_path / "read-only"
    folder.mkdir()
    folder.chmod(0o555)
    return folder


@pytest.fixture
def sdt(request, tmp_path):
    """``sdt(*args, env=...)``: run the real command; the cache goes to the test's folder.

    In a module marked ``in_process`` (its commands end before any worker starts) the same
    call runs through the entry point in this process instead (``sdt_in_process``).
    """
    if request.node.get_closest_marker("in_process"):
        return request.getfixturevalue("sdt_in_process")

    def run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
        return run_sdt(*args, env={"SDT_CACHE_DIR": str(tmp_path / "cache"), **(env or {})})

    return run


#: lines a benchmark prints before it starts: the estimate every one prints first, and the
#: warning of one whose sensors leave the reference out (as most tests do, to stay small)
_BEFORE_THE_RUN = ("note: this benchmark is ", "warning: the reference ")


def without_estimate(stderr: str) -> str:
    """``stderr`` less the ``note: this benchmark is …`` line every benchmark prints first
    (and the ``warning: the reference … is not among the sensors`` line).

    Tests of what a benchmark reports at its end compare the rest exactly.
    """
    return "".join(
        line for line in stderr.splitlines(keepends=True) if not line.startswith(_BEFORE_THE_RUN)
    )
