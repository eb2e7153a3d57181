"""``sdt benchmark`` says how long it expects to take, and on what that rests, before it starts.

On main only a benchmark estimated at over an hour printed its estimate, and
``sdt explore``'s estimate (65 s for a run that took 649 s on a loaded machine)
did not say what it assumed. Now every benchmark prints one ``note:`` line
with its runs, featurised signals and estimated time on N processes, and the
assumption behind the time, before any work.

The note, not the processes, is the subject: ``sdt`` runs in this process (``in_process``)
with ``--jobs 1``, so no worker starts.
"""

from __future__ import annotations

import re

import pandas as pd
import pytest

pytestmark = pytest.mark.in_process

ARGS = ("--quick", "--machines", "Motor-2", "--channels", "ch1", "--sensors", "adxl345")
ONE = ("--jobs", "1")  # this process only: no worker starts


def test_the_estimate_and_its_assumption_are_printed_before_the_run(sdt, tmp_path):
    out = tmp_path / "a"
    done = sdt("benchmark", *ARGS, *ONE, "--classifiers", "lr", "--no-report", "--out", str(out))
    assert done.returncode == 0, done.stderr
    notes = [line for line in done.stderr.splitlines() if line.startswith("note: ")]
    assert len(notes) == 1, done.stderr
    # 3 scenarios x 2 repeats x 1 classifier; 15 Motor-2 recordings of ch1 x 2 noise draws
    found = re.fullmatch(
        r"note: this benchmark is (\d+) runs and (\d+) featurised signals, estimated \d+ s "
        r"on (\d+) process(es)? \((.*)\)",
        notes[0],
    )
    assert found, notes[0]
    assert int(found[1]) == 6 == len(pd.read_csv(out / "results.csv"))
    assert int(found[2]) == 30
    assert int(found[3]) >= 1
    assert "reference machine" in found[5] and "a loaded or slower machine takes longer" in found[5]
    assert done.stderr.index(notes[0]) == 0  # before anything else the run prints
