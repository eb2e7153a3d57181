"""The order work is submitted in: longest first, so many workers finish together.

A pool that is handed its longest tasks last ends with one worker computing
alone (the issue that asked for this measured 286 s of a 850 s benchmark on
16 cores spent on the last 15 MLP fits). Submitting the longest tasks first
(the LPT rule) lets the short ones fill the gaps at the end.

A run's expected time is the estimate's model (:data:`~.estimate.RUN_SECONDS`,
``a + b * n_train`` for its classifier) times a factor per classifier learned
from what earlier benchmarks' runs took on this machine: the sum of their
measured fit times over the sum of their modelled times, kept in
``run_timings.json`` in the feature cache (shared by every benchmark using
that cache). A classifier the model does not know (a plugin) without history
is costed as the slowest built-in. A recording's featurisation is costed by
its samples.

The order changes no result: every run carries its own seed and data and is
stored under its own key, and the results table is assembled in plan order.
Ties keep the plan's order (the sort is stable).
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path

from ..io import atomic_write_text
from .classify import RunResult, RunTask
from .estimate import RUN_SECONDS
from .featurise import FeatureJob

__all__ = [
    "TIMINGS_FILE",
    "learn_factors",
    "longest_first",
    "model_seconds",
    "read_factors",
    "recordings_longest_first",
    "write_factors",
]

#: per-classifier factors (measured / modelled run time), in the feature cache folder
TIMINGS_FILE = "run_timings.json"
_SLOWEST = max(RUN_SECONDS.values(), key=lambda ab: ab[0] + 1000 * ab[1])


def model_seconds(classifier: str, n_train: int) -> float:
    """The estimate's single-thread seconds for one run of ``classifier`` on ``n_train``."""
    a, b = RUN_SECONDS.get(classifier, _SLOWEST)
    return a + b * n_train


def learn_factors(runs: Iterable[RunResult]) -> dict[str, float]:
    """classifier -> measured over modelled seconds, from finished (ok) runs."""
    measured: dict[str, float] = {}
    modelled: dict[str, float] = {}
    for run in runs:
        if run.status != "ok":
            continue
        name = str(run.labels.get("classifier"))
        measured[name] = measured.get(name, 0.0) + float(run.fit_seconds)
        modelled[name] = modelled.get(name, 0.0) + model_seconds(name, run.n_train)
    return {n: measured[n] / modelled[n] for n in sorted(measured) if modelled[n] > 0}


def read_factors(cache_dir: str | Path) -> dict[str, float]:
    """The factors stored in ``cache_dir`` ({} when none or unreadable: only an order)."""
    try:
        data = json.loads((Path(cache_dir) / TIMINGS_FILE).read_text())
    except (OSError, ValueError):
        return {}
    if not isinstance(data, dict):
        return {}
    return {
        str(k): float(v)
        for k, v in data.items()
        if isinstance(v, int | float) and not isinstance(v, bool) and v > 0
    }


def write_factors(cache_dir: str | Path, factors: Mapping[str, float]) -> None:
    """Merge ``factors`` into the cache's timings file (atomically; failures are ignored:
    the file only orders work)."""
    if not factors:
        return
    merged = {**read_factors(cache_dir), **factors}
    with contextlib.suppress(OSError):
        atomic_write_text(Path(cache_dir) / TIMINGS_FILE, json.dumps(merged, indent=1))


def longest_first(tasks: Sequence[RunTask], factors: Mapping[str, float]) -> list[RunTask]:
    """``tasks`` by expected run time, longest first; equal times keep their order."""

    def expected(task: RunTask) -> float:
        name = task.classifier.name
        return factors.get(name, 1.0) * model_seconds(name, len(task.y_train))

    return sorted(tasks, key=expected, reverse=True)


def recordings_longest_first(jobs: Sequence[FeatureJob]) -> list[FeatureJob]:
    """Featurisation jobs by their recording's samples, largest first (stable)."""
    return sorted(
        jobs,
        key=lambda j: j.recording.total_samples,
        reverse=True,
    )
