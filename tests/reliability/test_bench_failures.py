"""A classifier that fails in every run makes `sdt benchmark` exit 1; results are still written."""

from __future__ import annotations

import pandas as pd
from typer.testing import CliRunner

from sdt_framework.cli.main import app

from .conftest import without_estimate

PLUGIN = """
from sdt_framework import ClassifierSpec, hookimpl


class Broken:
    def __init__(self, random_state=None):
        pass

    def fit(self, x, y):
        raise RuntimeError("no convergence today")


class Fussy:
    '''Refuses training sets under 30 windows (forward and backward here), fits otherwise.'''

    def __init__(self, random_state=None):
        pass

    def fit(self, x, y):
        if len(y) < 30:
            raise ValueError(f"needs 30 windows, got {len(y)}")
        self.label_ = int(y[0])
        return self

    def predict(self, x):
        return [self.label_] * len(x)


@hookimpl
def register_classifiers(register):
    register(ClassifierSpec(name="broken", estimator="failing_plugin:Broken"))
    register(ClassifierSpec(name="fussy", estimator="failing_plugin:Fussy"))
"""


def run(tmp_path, classifiers: str):
    config = tmp_path / "small.toml"
    config.write_text(
        "[benchmark]\ndataset_options = { duration = 1.5 }\nmachines = ['Motor-2']\n"
        "channels = ['ch1', 'ch4']\nsensors = ['adxl345']\nrepeats = 2\njobs = 1\n"
        f"report = false\ncache_dir = '{tmp_path / 'cache'}'\n"
    )
    out = tmp_path / classifiers.replace(",", "-")
    result = CliRunner().invoke(
        app, ["benchmark", str(config), "--classifiers", classifiers, "--out", str(out)]
    )
    return result, out


def test_a_classifier_failing_in_every_run_exits_1_with_a_summary(fake_dist, tmp_path):
    fake_dist("failing-plugin", {"failing": "failing_plugin"}, {"failing_plugin": PLUGIN})
    result, out = run(tmp_path, "lr,broken")
    assert result.exit_code == 1, result.output
    assert without_estimate(result.stderr).strip() == (
        "error: classifier 'broken' failed in all 6 of 6 runs "
        "(first error: RuntimeError: no convergence today)"
    )
    results = pd.read_csv(out / "results.csv")  # still written, failures included
    assert results.groupby("classifier")["status"].agg(set).to_dict() == {
        "broken": {"error"},
        "lr": {"ok"},
    }
    assert "12 runs (12 computed, 0 resumed, 6 failed)" in result.stdout


def test_a_classifier_failing_in_some_runs_is_a_warning_and_exit_0(fake_dist, tmp_path):
    fake_dist("failing-plugin", {"failing": "failing_plugin"}, {"failing_plugin": PLUGIN})
    result, out = run(tmp_path, "lr,fussy")
    assert result.exit_code == 0, result.output
    assert without_estimate(result.stderr).strip() == (
        "warning: classifier 'fussy' failed in 4 of 6 runs "
        "(first error: ValueError: needs 30 windows, got 24)"
    )
    fussy = pd.read_csv(out / "results.csv").query("classifier == 'fussy'")
    assert fussy.groupby("scenario")["status"].agg(set).to_dict() == {
        "backward": {"error"},
        "forward": {"error"},
        "interpolation": {"ok"},
    }
