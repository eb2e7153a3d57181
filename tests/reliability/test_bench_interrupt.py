"""Ctrl-C during a classifier fit: nothing half-trained is stored, exit 130, resume is exact.

scikit-learn's MLPClassifier catches KeyboardInterrupt inside ``fit``, warns
"Training interrupted by user" and returns a half-trained model. The
``stopped-mlp`` plugin below is that MLP with the paper's hyperparameters; while
the flag file named by ``$SDT_TEST_CTRL_C`` exists, it sends itself SIGINT (what
a terminal's Ctrl-C does) in its third epoch, once.
"""

from __future__ import annotations

import json
import shlex

import pandas as pd
import pytest
from typer.testing import CliRunner

from sdt_framework import build_registry
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import plan_benchmark, run_benchmark
from sdt_framework.cli.main import app

PLUGIN = """
import os
import signal

from sklearn.neural_network import MLPClassifier

from sdt_framework import ClassifierSpec, hookimpl
from sdt_plugins.classifiers.mlp import MLP


class StoppedMLP(MLPClassifier):
    def _update_no_improvement_count(self, *args, **kwargs):
        flag = os.environ.get("SDT_TEST_CTRL_C", "")
        if self.n_iter_ == 3 and flag and os.path.exists(flag):
            os.remove(flag)
            os.kill(os.getpid(), signal.SIGINT)
        return super()._update_no_improvement_count(*args, **kwargs)


@hookimpl
def register_classifiers(register):
    register(ClassifierSpec(name="stopped-mlp", estimator="stopper_plugin:StoppedMLP",
                            params=MLP.params))
"""

CONFIG = """
[benchmark]
dataset_options = {{ duration = 1.5 }}
machines = ["Motor-2"]
channels = ["ch1", "ch4"]
sensors = ["adxl345"]
classifiers = ["lr", "stopped-mlp"]
repeats = 2
jobs = 1
report = false
cache_dir = "{cache}"
"""


@pytest.fixture
def flag(fake_dist, tmp_path, monkeypatch):
    """Install the stopped-mlp plugin; return its flag file (absent: no Ctrl-C)."""
    fake_dist("stopper-plugin", {"stopped-mlp": "stopper_plugin"}, {"stopper_plugin": PLUGIN})
    path = tmp_path / "ctrl-c"
    monkeypatch.setenv("SDT_TEST_CTRL_C", str(path))
    return path


def results_of(out) -> pd.DataFrame:
    return pd.read_csv(out / "results.csv").drop(columns="fit_seconds")


def test_an_interrupted_fit_is_never_stored_and_resuming_is_exact(flag, small_config, tmp_path):
    registry = build_registry()
    config = small_config(classifiers=["lr", "stopped-mlp"])
    out = tmp_path / "out"
    flag.touch()
    with pytest.raises(KeyboardInterrupt):
        run_benchmark(plan_benchmark(config, registry), out)
    assert not flag.exists()  # the Ctrl-C really happened inside the MLP's fit
    stored = [json.loads(p.read_text()) for p in (out / "runs").glob("*.json")]
    # runs go lr, stopped-mlp per (scenario, sensor, repeat): only the first lr run finished
    assert [s["labels"]["classifier"] for s in stored] == ["lr"]

    resumed = run_benchmark(plan_benchmark(config, registry), out)
    assert (resumed.runs_resumed, resumed.runs_computed) == (1, 11)
    clean = run_benchmark(plan_benchmark(config, registry), tmp_path / "clean")
    pd.testing.assert_frame_equal(
        tidy(resumed.runs)[0].drop(columns="fit_seconds"),
        tidy(clean.runs)[0].drop(columns="fit_seconds"),
    )


def test_ctrl_c_exits_130_with_the_exact_command_that_resumes(flag, tmp_path):
    config = tmp_path / "small.toml"
    config.write_text(CONFIG.format(cache=tmp_path / "cache"))
    out = tmp_path / "out"
    flag.touch()
    first = CliRunner().invoke(app, ["benchmark", str(config), "--out", str(out)])
    assert first.exit_code == 130, first.output
    assert not flag.exists()
    # the last line (sklearn may warn before it that batch_size exceeds these tiny training sets)
    line = first.stderr.strip().splitlines()[-1]
    assert line.startswith("interrupted: 1 finished run kept in")
    assert "Traceback" not in first.stderr and "Training interrupted" not in first.stderr
    command = shlex.split(line.split("resume with: ", 1)[1])
    assert command == ["sdt", "benchmark", str(out / "config.toml"), "--out", str(out)]

    resumed = CliRunner().invoke(app, command[1:])
    assert resumed.exit_code == 0, resumed.output
    assert "12 runs (11 computed, 1 resumed, 0 failed)" in resumed.stdout
    clean = CliRunner().invoke(app, ["benchmark", str(config), "--out", str(tmp_path / "clean")])
    assert clean.exit_code == 0, clean.output
    pd.testing.assert_frame_equal(results_of(out), results_of(tmp_path / "clean"))
