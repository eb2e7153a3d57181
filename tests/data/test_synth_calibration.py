"""Regression guard: the synthetic pump keeps fault information under the paper's pipeline.

One generator seed, the reduced protocol of ``benchmarks/calibrate_pump.py``
(reference chain, paper8, logistic regression, one repetition) through the
package's own benchmark API. It asserts what the physics of the fault
signatures implies, not exact scores:

- both cavitation classes carry a mark that no other class has at any level
  (suction: kHz bursts, kurtosis far above 3; discharge: a continuous hiss with
  sub-synchronous recirculation, no bursts), so a linear model separates them
  from the rest between trained levels and keeps finding them outside;
- a class's runs share their campaign and the test levels of interpolation lie
  between the trained ones, while backward extrapolation tests the weakest
  signatures on a model of the strongest: interpolation scores above backward
  on both machines.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from sdt_framework.bench.config import load_config
from sdt_framework.bench.plan import plan_benchmark
from sdt_framework.bench.results import tidy
from sdt_framework.bench.runner import run_benchmark
from sdt_framework.registry import build_registry


@pytest.fixture(scope="module")
def reference_chain(tmp_path_factory: pytest.TempPathFactory):
    where: Path = tmp_path_factory.mktemp("calibration")
    config = load_config(
        None,
        {
            "sensors": ["wilcoxon-786b10"],
            "classifiers": ["lr"],
            "repeats": 1,
            "jobs": 1,
            "report": False,
            "cache_dir": str(where / "cache"),
            "dataset_options": {"seed": 0},
        },
    )
    result = run_benchmark(plan_benchmark(config, build_registry()), where / "out")
    results, per_class, _ = tidy(result.runs)
    return results, per_class


def test_cavitation_classes_are_recognised_in_every_scenario(reference_chain) -> None:
    _, per_class = reference_chain
    cavitation = per_class[per_class["class"].str.startswith("cavitation")]
    f1 = cavitation.set_index(["scenario", "class"])["f1"]
    assert len(f1) == 2 * 3
    # between trained levels the mark is unmistakable ...
    assert (f1["interpolation"] >= 0.9).all(), f1.to_dict()
    # ... and it persists across levels: far above the 1/9 of a guess in every scenario
    assert (f1 >= 0.3).all(), f1.to_dict()


def test_interpolation_beats_backward_extrapolation(reference_chain) -> None:
    results, _ = reference_chain
    f1 = results.set_index(["machine", "scenario"])["macro_f1"]
    assert f1[("Motor-4", "interpolation")] > f1[("Motor-4", "backward")] + 0.1
    assert f1[("Motor-2", "interpolation")] > f1[("Motor-2", "backward")]
