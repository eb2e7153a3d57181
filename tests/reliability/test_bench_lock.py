"""Two ``sdt benchmark --out SAME`` at once: the second is refused, naming the first one.

On main both computed everything and overwrote each other's files. The first
to claim the folder now holds a lock for as long as it runs; the second gets
one ``error:`` line naming the folder and the first one's process, exit 2.
A lock left by a killed benchmark (SIGKILL: no chance to clean up) is taken
over by the next run, which resumes. The first benchmark is frozen with
SIGSTOP once it has claimed the folder, so the second surely meets it running.
The first runs in a process of its own (it is stopped and killed); the second and
the third go through sdt's entry point in the test's process.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pandas as pd
import pytest

ARGS = ["--quick", "--machines", "Motor-2", "--channels", "ch1", "--sensors", "adxl345"]
ARGS += ["--classifiers", "lr", "--no-report"]


def test_a_second_benchmark_on_a_running_folder_is_refused(sdt_in_process, tmp_path):
    sdt = sdt_in_process  # the cache in tmp_path/cache, as the first's
    out = tmp_path / "same"
    env = {**os.environ, "SDT_CACHE_DIR": str(tmp_path / "cache")}
    first = subprocess.Popen(
        [sys.executable, "-m", "sdt_framework", "benchmark", *ARGS, "--out", str(out)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        env=env,
        start_new_session=True,
    )
    try:
        deadline = time.monotonic() + 300
        while not (out / ".sdt-results.json").exists():
            if first.poll() is not None or time.monotonic() > deadline:
                pytest.fail("the first benchmark never claimed its folder")
            time.sleep(0.02)
        os.killpg(first.pid, signal.SIGSTOP)  # running, holding the folder

        second = sdt("benchmark", *ARGS, "--out", str(out))
        assert second.returncode == 2
        assert second.stderr.strip() == (
            f"error: --out {out} is in use by another sdt benchmark (process {first.pid}); "
            f"wait for it to finish (then run the same command to resume), or choose another --out"
        )
        assert not (out / "results.csv").exists()
    finally:
        os.killpg(first.pid, signal.SIGKILL)  # as a power cut or the OOM killer would
        first.wait(timeout=60)

    assert (out / ".sdt-lock").read_text().strip() == str(first.pid)  # left behind
    third = sdt("benchmark", *ARGS, "--out", str(out))
    assert third.returncode == 0, third.stderr
    results = pd.read_csv(out / "results.csv")
    assert len(results) == 6 and (results["status"] == "ok").all()  # 3 scenarios x 2 repeats
