"""Kill test: a real `sdt benchmark --quick`, stopped in its classifier phase, then resumed.

Ctrl-C is simulated as a terminal sends it: SIGINT to the whole process group
(the main process and its loky workers). SIGKILL gives no chance to clean up
at all. Either way, resuming must give exactly the Macro F1 of a clean run.
The classifier phase is detected by the first run file appearing on disk.
Only the stopped benchmarks run in processes of their own; the clean run and the
resumes go through sdt's entry point in the test's process.
"""

from __future__ import annotations

import os
import re
import shlex
import signal
import subprocess
import sys
import time

import pandas as pd
import pytest

from sdt_framework.bench.results import RUN_COLUMNS

from ..helpers import sdt_here

QUICK = ["--quick", "--machines", "Motor-2", "--sensors", "adxl345", "--classifiers", "lr,mlp"]
QUICK += ["--repeats", "4"]  # enough runs (about 2 s of fitting) to land a signal among them
RUNS = 24  # 3 scenarios x 1 sensor x 2 classifiers x 4 repeats
SDT = [sys.executable, "-m", "sdt_framework"]


def sigint_as_in_a_terminal() -> None:
    """Default SIGINT in the child, as a terminal's foreground job has it."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def start(out, *extra: str) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [*SDT, "benchmark", *QUICK, "--no-report", "--out", str(out), *extra],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # its own process group, as a terminal's foreground job
        preexec_fn=sigint_as_in_a_terminal,  # even when this shell ignores SIGINT
    )


def stop_in_classifier_phase(process: subprocess.Popen[str], out, sig: int) -> tuple[int, str]:
    deadline = time.monotonic() + 300
    while not list((out / "runs").glob("*.json")):
        if process.poll() is not None or time.monotonic() > deadline:
            process.kill()
            pytest.fail(f"never reached the classifier phase: {process.communicate()[1]}")
        time.sleep(0.02)
    os.killpg(process.pid, sig)
    _, stderr = process.communicate(timeout=120)
    stored = len(list((out / "runs").glob("*.json")))
    assert 1 <= stored < RUNS, f"stopped with {stored} of {RUNS} runs stored"
    return process.returncode, stderr


def macro_f1(out) -> pd.Series:
    results = pd.read_csv(out / "results.csv")
    assert len(results) == RUNS and (results["status"] == "ok").all()
    return results.set_index(RUN_COLUMNS)["macro_f1"].sort_index()


def finish(*args: str) -> None:
    """``sdt ARGS`` run to its end (in this process: no signal is sent to it)."""
    done = sdt_here(*args)
    assert done.returncode == 0, done.stderr


def test_sigint_and_sigkill_in_the_classifier_phase_then_resume(tmp_path, monkeypatch):
    monkeypatch.setenv("SDT_CACHE_DIR", str(tmp_path / "cache"))
    finish("benchmark", *QUICK, "--no-report", "--jobs", "1", "--out", str(tmp_path / "c"))
    clean = macro_f1(tmp_path / "c")

    out = tmp_path / "ctrl-c"
    code, stderr = stop_in_classifier_phase(start(out, "--jobs", "2"), out, signal.SIGINT)
    assert code == 130, stderr
    assert "Traceback" not in stderr
    line = stderr.strip().splitlines()[-1]
    assert re.match(r"interrupted: \d+ finished runs? kept in ", line), line
    command = shlex.split(line.split("resume with: ", 1)[1])
    assert command == ["sdt", "benchmark", str(out / "config.toml"), "--out", str(out)]
    finish(*command[1:])
    pd.testing.assert_series_equal(macro_f1(out), clean)

    out = tmp_path / "killed"
    code, _ = stop_in_classifier_phase(start(out, "--jobs", "1"), out, signal.SIGKILL)
    assert code == -signal.SIGKILL
    finish("benchmark", *QUICK, "--no-report", "--out", str(out), "--jobs", "1")  # again
    pd.testing.assert_series_equal(macro_f1(out), clean)
