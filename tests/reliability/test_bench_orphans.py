"""Workers end with ``sdt benchmark`` when it is killed outright (SIGKILL, the OOM killer).

On main the loky workers of a SIGKILLed benchmark computed on for minutes,
holding the cores and memory. Each worker now watches its parent and exits
once it is gone. The test starts a real benchmark with two worker processes
(``--jobs 2``: one this short runs in its own process by default), waits
until its workers are featurising (a feature-cache entry on disk), kills the
main process with SIGKILL, and polls until every worker has ended (30 s is a
generous bound: the watch looks twice a second).
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import psutil
import pytest

ARGS = ["--quick", "--sensors", "adxl345", "--classifiers", "lr", "--no-report", "--jobs", "2"]


def _workers(main: psutil.Process) -> list[psutil.Process]:
    return [child for child in main.children() if "loky" in " ".join(child.cmdline())]


def _alive(process: psutil.Process) -> bool:
    try:
        return process.is_running() and process.status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


def test_sigkill_of_the_main_process_ends_its_workers(tmp_path):
    cache = tmp_path / "cache"
    command = [sys.executable, "-m", "sdt_framework", "benchmark", *ARGS]
    started = subprocess.Popen(
        [*command, "--out", str(tmp_path / "a")],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        env={**os.environ, "SDT_CACHE_DIR": str(cache)},
        start_new_session=True,
    )
    main = psutil.Process(started.pid)
    workers: list[psutil.Process] = []
    try:
        deadline = time.monotonic() + 300
        while not (workers and any((cache / "features").rglob("*.npz"))):
            if started.poll() is not None or time.monotonic() > deadline:
                pytest.fail(f"the workers never started featurising: {started.stderr.read()}")
            workers = _workers(main)
            time.sleep(0.1)
        workers = _workers(main)
        assert workers
        os.kill(started.pid, signal.SIGKILL)
        started.wait(timeout=30)
        deadline = time.monotonic() + 30
        while any(_alive(w) for w in workers) and time.monotonic() < deadline:
            time.sleep(0.2)
        assert not [w.pid for w in workers if _alive(w)], "workers outlived the killed benchmark"
    finally:
        for worker in workers:  # only the processes this test started
            if _alive(worker):
                worker.kill()
        if started.poll() is None:
            started.kill()
        started.stderr.close()
