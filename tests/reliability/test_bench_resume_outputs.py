"""Every output file of a resumed folder equals the uninterrupted run's.

A benchmark (and a sweep) is run once without interruption; then the same
configuration is run again into that folder (a full resume), and into a new
folder that a real ``sdt`` process fills until SIGINT (as a terminal's Ctrl-C:
the whole process group) or SIGTERM (``kill``: the main process only) stops
it, resumed with the command it prints. Each table is read back and compared
exactly with the uninterrupted run's: results, per_class, confusion,
per_recording, features, allocation, skipped, Table 4, the configuration,
summary.json (less its counters and timings) and the explore tables. The
only column left out is ``fit_seconds``, a wall-clock time that differs
between any two runs.

The ``slow-lr`` plugin below is the paper's logistic regression with a pause
before each fit while ``$SDT_TEST_SLOW_FIT`` is set, so that a signal lands
in the classifier phase; without the variable it is plain ``lr``. Only the
commands that are stopped run in a process of their own; the uninterrupted
runs and the resumes go through the same entry point in the test's process.
"""

from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from ..helpers import sdt_here
from .conftest import without_estimate

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
                            params={"max_iter": 2000, "class_weight": "balanced"},
                            seed_param="random_state"))
"""

PROTOCOL = """
dataset_options = {{ duration = 1.5 }}
machines = ["Motor-2"]
channels = ["ch1", "ch4"]
classifiers = ["slow-lr"]
repeats = 2
jobs = 1
report = false
cache_dir = "{cache}"
"""
BENCHMARK = '[benchmark]\nsensors = ["wilcoxon-786b10", "adxl345"]\n' + PROTOCOL
SWEEP = (
    """
[sweep]
base = "adxl345"
target = {{ max_loss = 0.1 }}

[sweep.axes.noise_density_ug_rthz]
levels = [90, 290]

[benchmark]
scenarios = ["forward"]
"""
    + PROTOCOL
)

BENCH_TABLES = [
    "results.parquet",
    "results.csv",
    "per_class.parquet",
    "confusion.parquet",
    "per_recording.parquet",
    "features.parquet",
    "allocation.csv",
    "skipped.csv",
]
EXPLORE_TABLES = [
    "explore.parquet",
    "points.csv",
    "skipped_points.csv",
    "main_effects.csv",
    "sensitivity.csv",
    "min_spec.csv",
    "min_spec_points.csv",
    "pareto.csv",
]
#: summary.json entries that describe how the folder was filled, not what it holds
HOW_FILLED = {
    "runs_computed",
    "runs_resumed",
    "feature_blocks_computed",
    "feature_blocks_cached",
    "seconds",
}
SDT = [sys.executable, "-m", "sdt_framework"]


@pytest.fixture(scope="module")
def env(tmp_path_factory) -> dict[str, str]:
    """slow-lr installed for the ``sdt`` processes of this module, and their feature cache."""
    root = tmp_path_factory.mktemp("resume")
    site = root / "site"
    (site / "slow_plugin-1.0.dist-info").mkdir(parents=True)
    (site / "slow_plugin.py").write_text(PLUGIN)
    (site / "slow_plugin-1.0.dist-info" / "METADATA").write_text(
        "Metadata-Version: 2.1\nName: slow-plugin\nVersion: 1.0\n"
    )
    (site / "slow_plugin-1.0.dist-info" / "entry_points.txt").write_text(
        "[sdt_framework]\nslow-lr = slow_plugin\n"
    )
    path = os.pathsep.join([str(site), os.environ.get("PYTHONPATH", "")])
    return {**os.environ, "PYTHONPATH": path, "SDT_CACHE_DIR": str(root / "cache")}


def _read(path: Path) -> pd.DataFrame:
    frame = pd.read_parquet(path) if path.suffix == ".parquet" else pd.read_csv(path)
    return frame.drop(columns="fit_seconds", errors="ignore")


def assert_same_outputs(got: Path, want: Path, tables: list[str], texts: list[str]) -> None:
    """Every listed file of ``got`` equals the one of ``want`` (tables exactly, as frames)."""
    for name in tables:
        pd.testing.assert_frame_equal(
            _read(got / name), _read(want / name), check_exact=True, obj=name
        )
    for name in texts:
        assert (got / name).read_text() == (want / name).read_text(), name
    summaries = [json.loads((d / "summary.json").read_text()) for d in (got, want)]
    assert [{k: v for k, v in s.items() if k not in HOW_FILLED} for s in summaries] == [
        {k: v for k, v in summaries[1].items() if k not in HOW_FILLED}
    ] * 2


def run(command: list[str], env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    """``command`` (``[*SDT, ARGS]``) through sdt's entry point in this process, with the
    module's cache and slow-lr's site (``env``'s ``PYTHONPATH``, first)."""
    assert command[: len(SDT)] == SDT, command
    site = Path(env["PYTHONPATH"].split(os.pathsep)[0])
    cache = {"SDT_CACHE_DIR": env["SDT_CACHE_DIR"]}
    done = sdt_here(*command[len(SDT) :], env=cache, site=site)
    assert done.returncode == 0, done.stderr
    return done


def stop_then_resume(command: list[str], out: Path, env: dict[str, str], sig: int) -> str:
    """Start ``command``, send ``sig`` once a run is stored, resume as told; the resume's stdout."""
    sigint_default = lambda: signal.signal(signal.SIGINT, signal.SIG_DFL)  # noqa: E731
    process = subprocess.Popen(
        command,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**env, "SDT_TEST_SLOW_FIT": "0.15"},
        start_new_session=True,  # its own process group, as a terminal's foreground job
        preexec_fn=sigint_default,  # even when this shell ignores SIGINT
    )
    deadline = time.monotonic() + 120
    while not list((out / "runs").glob("*.json")):
        if process.poll() is not None or time.monotonic() > deadline:
            process.kill()
            pytest.fail(f"never reached the classifier phase: {process.communicate()[1]}")
        time.sleep(0.02)
    if sig == signal.SIGINT:
        os.killpg(process.pid, sig)  # Ctrl-C reaches the whole foreground group
    else:
        os.kill(process.pid, sig)  # kill PID, a scheduler's time limit
    _, stderr = process.communicate(timeout=60)
    assert process.returncode == 128 + sig, stderr
    line = stderr.strip().splitlines()[-1]
    assert "Traceback" not in stderr and "finished run" in line and str(out) in line, stderr
    resume = shlex.split(re.search(r"\(?(sdt \w+ [^()]*)\)?$", line).group(1))
    assert resume[:2] == ["sdt", command[3]], line
    return run([*SDT, *resume[1:]], env).stdout


@pytest.fixture(scope="module")
def clean(env) -> tuple[Path, Path]:
    """An uninterrupted benchmark, run once for the module: (its config file, its folder)."""
    root = Path(env["SDT_CACHE_DIR"]).parent
    config = root / "bench.toml"
    config.write_text(BENCHMARK.format(cache=env["SDT_CACHE_DIR"]))
    out = root / "clean"
    run([*SDT, "benchmark", str(config), "--out", str(out)], env)
    return config, out


BENCH_TEXTS = ["table4.md", "config.toml"]


def test_a_full_resume_rewrites_every_file_as_it_was(clean, env, tmp_path):
    config, out = clean
    again = tmp_path / "again"
    shutil.copytree(out, again)
    stdout = run([*SDT, "benchmark", str(config), "--out", str(again)], env).stdout
    assert "12 runs (0 computed, 12 resumed, 0 failed)" in stdout
    assert len(pd.read_parquet(again / "per_recording.parquet")) > 0
    assert_same_outputs(again, out, BENCH_TABLES, BENCH_TEXTS)


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["sigint", "sigterm"])
def test_stopped_and_resumed_equals_the_uninterrupted_run(clean, env, tmp_path, sig):
    config, out = clean
    resumed = tmp_path / "resumed"
    command = [*SDT, "benchmark", str(config), "--out", str(resumed)]
    stdout = stop_then_resume(command, resumed, env, sig)
    assert "resumed, 0 failed)" in stdout and " 0 resumed" not in stdout
    assert_same_outputs(resumed, out, BENCH_TABLES, BENCH_TEXTS)


#: the folder layout these tests compare is the exhaustive strategy's (one benchmark folder)
EXHAUSTIVE = ["--strategy", "exhaustive"]


def test_an_explore_folder_after_sigterm_and_resumes_equals_the_uninterrupted_one(env, tmp_path):
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(SWEEP.format(cache=env["SDT_CACHE_DIR"]))
    out = tmp_path / "clean"
    run([*SDT, "explore", str(sweep), "--out", str(out), "--no-report", *EXHAUSTIVE], env)

    resumed = tmp_path / "resumed"
    command = [*SDT, "explore", str(sweep), "--out", str(resumed), "--no-report", *EXHAUSTIVE]
    stop_then_resume(command, resumed, env, signal.SIGTERM)
    texts = ["table4.md", "config.toml", "sweep.toml"]
    assert_same_outputs(resumed, out, BENCH_TABLES + EXPLORE_TABLES, texts)

    run(command, env)  # and a full resume of the finished folder
    assert_same_outputs(resumed, out, BENCH_TABLES + EXPLORE_TABLES, texts)


def test_run_files_without_per_recording_counts_are_recomputed_with_one_warning(
    clean, env, tmp_path
):
    config, out = clean
    old = shutil.copytree(out, tmp_path / "old")
    files = sorted((old / "runs").glob("*.json"))
    for path in files:  # as a version that did not store the counts wrote them
        record = json.loads(path.read_text())
        del record["per_recording"]
        path.write_text(json.dumps(record))
    done = run([*SDT, "benchmark", str(config), "--out", str(old)], env)
    assert "12 runs (12 computed, 0 resumed, 0 failed)" in done.stdout
    assert without_estimate(done.stderr).strip() == (
        f"warning: ignoring 12 run files in {old / 'runs'} written without per-recording "
        f"counts by an older version (e.g. {files[0].name}); their runs will be computed again"
    )
    assert_same_outputs(old, out, BENCH_TABLES, BENCH_TEXTS)
