"""Generated runs are kept for the process: each run is generated once however its
channels are read (plugins/datasets/synthetic_pump/kept.py)."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
from sdt_plugins.datasets.synthetic_pump import dataset as synthetic
from sdt_plugins.datasets.synthetic_pump import kept
from sdt_plugins.datasets.synthetic_pump.generate import generate_run

from sdt_framework.signals.parsed import Kept


@pytest.fixture
def calls(monkeypatch) -> list[tuple]:
    """Every run the dataset generates, from an empty memo (restored after the test)."""
    made: list[tuple] = []

    def counting(machine, condition, level, **options):
        made.append((machine, condition, level))
        return generate_run(machine, condition, level, **options)

    monkeypatch.setattr(synthetic, "generate_run", counting)
    runs = Kept(kept.KEEP_BYTES, lambda run: sum(x.nbytes for x in run.values()))
    monkeypatch.setattr(kept, "RUNS", runs)
    return made


def _open(**options):
    return synthetic.open_synthetic(duration=0.25, machines="Motor-2", seed=5, **options)


def test_two_datasets_and_pickled_copies_generate_each_run_once(calls) -> None:
    first = _open()
    runs = first.runs()
    for recordings in runs.values():
        for r in recordings:
            pickle.loads(pickle.dumps(r)).load()  # as a worker gets it: its own dataset copy
    for r in _open().recordings():  # a second benchmark over the same runs
        r.load()
    assert len(calls) == len(set(calls)) == len(runs) == 15


def test_kept_samples_are_the_generators_read_only(calls) -> None:
    recording = _open().recordings()[7]
    machine, run = recording.machine, recording.run
    condition, level = run.rsplit(" ", 1)
    want = generate_run(
        machine, condition, int(level), channels=("ch1", "ch2", "ch3", "ch4", "ch5"),
        acquisitions=1, duration_s=0.25, seed=5,
    )[recording.channel]  # fmt: skip
    got = recording.load()
    assert np.array_equal(got, want)
    assert not got.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        got[0, 0] = 1.0


def test_the_kept_runs_stay_within_the_budget_and_the_last_is_kept_whatever_its_size(
    calls, monkeypatch
) -> None:
    run_bytes = 5 * round(0.25 * synthetic.FS_HZ) * 8  # 5 channels, one acquisition
    monkeypatch.setattr(kept.RUNS, "keep_bytes", 3 * run_bytes)
    recordings = _open().recordings()
    for r in recordings:
        r.load()
        assert kept.RUNS.held <= 3 * run_bytes
    assert len(kept.RUNS) == 3
    recordings[-1].load()  # the most recent: kept
    assert len(calls) == 15
    recordings[0].load()  # the first: long gone
    assert len(calls) == 16
    monkeypatch.setattr(kept.RUNS, "keep_bytes", run_bytes // 2)
    recordings[30].load()  # over the budget alone: kept, on its own
    assert len(kept.RUNS) == 1 and len(calls) == 17
    recordings[31].load()  # the same run's next channel
    assert len(calls) == 17
