"""The caveat about a class tested on one physical run names the class.

From a new user's walk-through: "some class has a single physical test run in
Motor-2 backward, ..." left the user to find which class in allocation.csv.
Now each cell names its classes, or says every class.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from sdt_framework.verdict import compare, verdict


def _results() -> pd.DataFrame:
    rng = np.random.default_rng(0)
    rows = [
        dict(machine=m, scenario=s, sensor=sensor, classifier=c, repeat=r, status="ok",
             macro_f1=0.6 + rng.normal(0, 0.01))
        for m in ("M2", "M4")
        for s in ("forward", "backward")
        for c in ("lr", "knn", "rf")
        for r in range(5)
        for sensor in ("ref", "a", "b")
    ]  # fmt: skip
    return pd.DataFrame(rows)


def _allocation() -> pd.DataFrame:
    """Test runs per class: M2 forward: healthy 2, fault 1; M4 backward: 1 each; else 2."""
    rows = []
    for machine in ("M2", "M4"):
        for scenario in ("forward", "backward"):
            for condition in ("healthy", "fault"):
                single = (machine, scenario) == ("M4", "backward") or (
                    (machine, scenario, condition) == ("M2", "forward", "fault")
                )
                for k in range(1 if single else 2):
                    run = f"{condition}-{k}"
                    rows.append(dict(machine=machine, scenario=scenario, condition=condition,
                                     run=run, side="test"))  # fmt: skip
                rows.append(dict(machine=machine, scenario=scenario, condition=condition,
                                 run=f"{condition}-train", side="train"))  # fmt: skip
    return pd.DataFrame(rows)


def test_the_caveat_names_the_classes_tested_on_one_run():
    comparison = compare(_results(), "ref", allocation=_allocation(), n_boot=50)
    caveats = [f.text for f in verdict(comparison) if f.scope == "caveat"]
    assert caveats == [
        "classes with a single physical test run: M2 forward (fault), M4 backward (every "
        "class): the recording CI there resamples that run's channels (simultaneous views of "
        "one event), not runs, so it understates run-to-run variation."
    ]
