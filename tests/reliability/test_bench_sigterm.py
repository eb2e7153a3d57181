"""SIGTERM is Ctrl-C's twin: finished runs kept, one line with the resume command, workers
stopped, exit 143 (128 + SIGTERM).

``kill PID``, a batch scheduler's time limit and ``docker stop`` send SIGTERM to
the main process only; its loky workers must not be left computing. The
``slow-lr`` plugin pauses before each fit while ``$SDT_TEST_SLOW_FIT`` is set,
so the signal lands while workers are busy.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time

import psutil
import pytest

from sdt_framework.bench.interrupt import Terminated, no_swallowed_interrupt, watch_interrupts

PLUGIN = """
import os
import time

from sklearn.linear_model import LogisticRegression

from sdt_framework import ClassifierSpec, hookimpl


class SlowLR(LogisticRegression):
    def fit(self, X, y, sample_weight=None):
        time.sleep(float(os.environ.get("SDT_TEST_SLOW_FIT", "0")))
        return super().fit(X, y, sample_weight)


@hookimpl
def register_classifiers(register):
    register(ClassifierSpec(name="slow-lr", estimator="slow_plugin:SlowLR",
                            params={"max_iter": 2000}, seed_param="random_state"))
"""

CONFIG = """
[benchmark]
dataset_options = {{ duration = 1.5 }}
machines = ["Motor-2"]
channels = ["ch1", "ch4"]
sensors = ["adxl345"]
classifiers = ["slow-lr"]
repeats = 4
jobs = 2
report = false
cache_dir = "{cache}"
"""


def test_sigterm_keeps_finished_runs_stops_the_workers_and_exits_143(fake_dist, tmp_path):
    site = fake_dist("slow-plugin", {"slow-lr": "slow_plugin"}, {"slow_plugin": PLUGIN})
    config = tmp_path / "small.toml"
    config.write_text(CONFIG.format(cache=tmp_path / "cache"))
    out = tmp_path / "out"
    env = {**os.environ, "PYTHONPATH": str(site), "SDT_TEST_SLOW_FIT": "0.5"}
    process = subprocess.Popen(
        [sys.executable, "-m", "sdt_framework", "benchmark", str(config), "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=env,
        start_new_session=True,
    )
    deadline = time.monotonic() + 120
    while not list((out / "runs").glob("*.json")):
        if process.poll() is not None or time.monotonic() > deadline:
            process.kill()
            pytest.fail(f"never reached the classifier phase: {process.communicate()[1]}")
        time.sleep(0.02)
    workers = psutil.Process(process.pid).children(recursive=True)
    assert workers, "the runs should be computed by worker processes (--jobs 2)"
    os.kill(process.pid, signal.SIGTERM)  # the main process only, as `kill PID` does
    _, stderr = process.communicate(timeout=60)

    assert process.returncode == 143, stderr
    assert "Traceback" not in stderr
    line = stderr.strip().splitlines()[-1]
    stored = len(list((out / "runs").glob("*.json")))
    assert 1 <= stored < 12  # 3 scenarios x 4 repeats: stopped part-way, finished runs kept
    assert re.fullmatch(
        rf"terminated: {stored} finished runs? kept in {re.escape(str(out))}; resume with: "
        rf"sdt benchmark {re.escape(str(out / 'config.toml'))} --out {re.escape(str(out))}",
        line,
    ), line
    gone_by = time.monotonic() + 10
    while any(w.is_running() and w.status() != psutil.STATUS_ZOMBIE for w in workers):
        assert time.monotonic() < gone_by, "workers still computing after the benchmark ended"
        time.sleep(0.1)


def test_a_sigterm_swallowed_by_a_fit_is_raised_again_as_terminated():
    """A fit that catches KeyboardInterrupt (sklearn's MLP does) never returns as finished."""
    swallowed = []
    with (
        pytest.raises(Terminated),
        watch_interrupts(terminate=True) as watch,
        no_swallowed_interrupt(),
    ):
        try:
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(1)
        except KeyboardInterrupt as exc:  # what MLPClassifier.fit does
            swallowed.append(exc)
    assert watch.terminated and isinstance(swallowed[0], Terminated)
    assert signal.getsignal(signal.SIGTERM) == signal.SIG_DFL  # put back as it was
