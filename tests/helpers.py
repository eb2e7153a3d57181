"""Helpers shared by tests in several folders (import as ``from ..helpers import ...``).

- :func:`run_sdt`: ``sdt`` in a real process, as a user types it (exit status,
  stdout and stderr exactly as printed), optionally under an address-space cap.
- :func:`sdt_here`: the same call and result through the console script's entry point
  in this process, for the commands of a test whose subject is not the process itself.
- :func:`run_watching_loky_workers`: a command run to its end while its loky workers are
  counted.
- :func:`six_recordings`: a manifest of six short ``.npy`` recordings, two
  classes, for tests that replace one of them with a bad file.
- :data:`EXPLORE_BENCHMARK`: the smallest ``[benchmark]`` table a sweep file
  can run (one machine, one channel, LR, one repetition, 1.5 s acquisitions).
"""

from __future__ import annotations

import contextlib
import io
import os
import resource
import subprocess
import sys
import threading
import time
import warnings
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pytest

__all__ = [
    "EXPLORE_BENCHMARK",
    "MANIFEST_HEADER",
    "run_sdt",
    "run_watching_loky_workers",
    "sdt_here",
    "six_recordings",
    "small_protocol",
]

MANIFEST_HEADER = "path,sampling_rate_hz,machine,condition,severity,recording_id,channel\n"

EXPLORE_BENCHMARK = """
[benchmark]
dataset_options = { duration = 1.5 }
classifiers = ["lr"]
machines = ["Motor-2"]
channels = ["ch1"]
scenarios = ["interpolation"]
repeats = 1
"""


def small_protocol(channels: int = 1, repeats: int = 1, scenarios: int = 1) -> dict:
    """A benchmark protocol of seconds: Motor-2, 1.5 s acquisitions, lr, one process.

    ``channels``: ch1 (1) or ch1 and ch4 (2); ``scenarios``: forward (1) or forward and
    interpolation (2); ``repeats``: repetitions. The explore and edge tests share it.
    """
    return {
        "dataset_options": {"duration": 1.5},
        "machines": ["Motor-2"],
        "channels": ["ch1", "ch4"][:channels],
        "classifiers": ["lr"],
        "scenarios": ["forward", "interpolation"][:scenarios],
        "repeats": repeats,
        "jobs": 1,
        "report": False,
    }


def _cap_address_space(limit: int) -> None:
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def entry_status(args: Iterable[str], monkeypatch) -> int:
    """``sdt ARGS`` through the console script's entry point in this process (``sys.argv`` set
    with ``monkeypatch``); its exit status, as the interpreter would exit with it."""
    from sdt_framework.cli.entry import main

    monkeypatch.setattr(sys, "argv", ["sdt", *args])
    try:
        main()
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else int(exc.code is not None)
    return 0


def run_sdt(
    *args: str,
    cwd: Path | None = None,
    env: Mapping[str, str] | None = None,
    without: Iterable[str] = (),
    memory_cap: int | None = None,
    timeout: float | None = None,
) -> subprocess.CompletedProcess[str]:
    """``sdt ARGS`` in a child process; never raises on a non-zero exit.

    The child's environment is this process's, less the names in ``without``,
    updated with ``env``. ``memory_cap`` (bytes) caps the child's address space
    (``ulimit -v``, which the framework's memory estimates honour), so a test of
    a huge input is refused, or ends in a MemoryError, whatever the machine has.
    """
    environ = {k: v for k, v in os.environ.items() if k not in set(without)} | dict(env or {})
    return subprocess.run(
        [sys.executable, "-m", "sdt_framework", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        env=environ,
        preexec_fn=None if memory_cap is None else lambda: _cap_address_space(memory_cap),
        timeout=timeout,
        check=False,
    )


def _as_a_fresh_interpreter_warns() -> None:
    """Python's default warning filters (each warning once per place; deprecations, import
    and resource warnings ignored outside ``__main__``), shown on ``sys.stderr``."""
    warnings.resetwarnings()
    warnings.simplefilter("default")
    for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
        warnings.simplefilter("ignore", category)
    warnings.showwarning = lambda message, category, filename, lineno, file=None, line=None: (
        sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))
    )


def sdt_here(
    *args: str, env: Mapping[str, str] | None = None, site: Path | None = None
) -> subprocess.CompletedProcess[str]:
    """``sdt ARGS`` as :func:`run_sdt` returns it (exit status, stdout, stderr), run through the
    console script's entry point in this process, with ``env`` set for the call.

    For a test's set-up and follow-up commands (the uninterrupted run a stopped one is
    compared with, the resume it prints): a child adds about 2.5 CPU-s of imports and checks
    nothing more. The command a signal, a memory cap or an orphan check is sent to keeps a
    process of its own (:func:`run_sdt`), as do runs whose worker processes must start fresh.
    ``site``, a folder of plugin distributions, is first on the import path for the call, as
    ``PYTHONPATH`` puts it for a child; the modules imported from it are forgotten after.
    Python's warnings are shown on the command's stderr with a fresh interpreter's filters,
    as a child would print them (pytest would otherwise record them out of sight).
    """
    out, err = io.StringIO(), io.StringIO()
    before = set(sys.modules)
    with pytest.MonkeyPatch.context() as patch, warnings.catch_warnings():
        _as_a_fresh_interpreter_warns()
        for name, value in (env or {}).items():
            patch.setenv(name, value)
        if site is not None:
            patch.syspath_prepend(str(site))
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = entry_status(args, patch)
    if site is not None:
        for name in set(sys.modules) - before:
            if str(getattr(sys.modules[name], "__file__", "") or "").startswith(str(site)):
                del sys.modules[name]
    return subprocess.CompletedProcess(["sdt", *args], code, out.getvalue(), err.getvalue())


def _loky_workers(pid: int) -> set[int]:
    import psutil

    found = set()
    for child in psutil.Process(pid).children(recursive=True):
        try:
            if "popen_loky" in " ".join(child.cmdline()):
                found.add(child.pid)
        except psutil.Error:
            continue
    return found


def run_watching_loky_workers(
    command: list[str], **popen: Any
) -> tuple[subprocess.CompletedProcess[str], set[int]]:
    """Run ``command`` (``subprocess.Popen`` options ``popen``) to its end, looking at its
    process tree every 50 ms: (its status and output, the loky worker processes seen)."""
    import psutil

    child = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **popen
    )
    seen: set[int] = set()

    def watch() -> None:
        while child.poll() is None:
            try:
                seen.update(_loky_workers(child.pid))
            except psutil.Error:
                return
            time.sleep(0.05)

    watcher = threading.Thread(target=watch)
    watcher.start()
    out, err = child.communicate(timeout=600)
    watcher.join()
    return subprocess.CompletedProcess(command, child.returncode, out, err), seen


def six_recordings(folder: Path, file_name: str = "m.csv") -> Path:
    """``folder/file_name``: six 2 s recordings at 20 kHz (``healthy0..2``, ``fault0..2``, the
    faults at twice the amplitude, severities 1-3), one machine ``m``, channel ``ch1``; the
    ``.npy`` files beside it. Returns the manifest's path."""
    rng = np.random.default_rng(0)
    lines = [MANIFEST_HEADER]
    for condition, gain in (("healthy", 1.0), ("fault", 2.0)):
        for index in range(3):
            name = f"{condition}{index}"
            np.save(folder / f"{name}.npy", gain * rng.normal(size=40_000))
            severity = index + 1 if gain > 1 else ""
            lines.append(f"{name}.npy,20000,m,{condition},{severity},{name},ch1\n")
    manifest = folder / file_name
    manifest.write_text("".join(lines), encoding="utf-8")
    return manifest
