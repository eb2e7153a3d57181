"""Tidy result tables, written atomically.

``results`` has one row per run (dataset, machine, scenario, sensor,
feature_set, classifier, repeat, unit (-1: the nominal profile), seed,
macro_f1, n_train, n_test, fit_seconds, status, error, and what it trained
and tested on: train_sensor, test_sensor, node; ``sensor`` is the row's
label: the sensor, ``TRAIN -> TEST`` for a transfer, ``... @ NODE`` for a
node); ``per_class``,
``confusion`` and ``per_recording`` (confusion counts per test recording) are
long tables keyed by the same run columns. Table 4 is built from ``results``
in :mod:`sdt_framework.bench.table4`.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

import pandas as pd

from ..csv_cells import escape_frame
from ..io import atomic_path
from .classify import RunResult
from .scenarios import natural, parse_speed_scenario
from .speed_split import speed_title

__all__ = [
    "RUN_COLUMNS",
    "SCENARIO_TITLES",
    "per_recording",
    "scenario_rank",
    "scenario_title",
    "tidy",
    "write_frame",
]

RUN_COLUMNS = [
    "dataset",
    "machine",
    "scenario",
    "sensor",
    "feature_set",
    "classifier",
    "repeat",
    "unit",
    "seed",
]
#: what a row trained and tested on: the sensor itself for ordinary runs (transfer and node
#: runs carry them in their labels); node: None for channel samples
CHAIN_COLUMNS = ["train_sensor", "test_sensor", "node"]
RESULT_COLUMNS = [
    *RUN_COLUMNS,
    "macro_f1",
    "n_train",
    "n_test",
    "fit_seconds",
    "status",
    "error",
    *CHAIN_COLUMNS,
]
SCENARIO_TITLES = {
    "forward": "Experiment A. Forward extrapolation",
    "backward": "Experiment B. Backward extrapolation",
    "interpolation": "Experiment C. Interpolation",
}


def scenario_title(name: object) -> str:
    """A scenario's heading: the paper's title, a speed transfer's (``Speed transfer:
    trained at 100, tested at 75``), else the name as given."""
    return SCENARIO_TITLES.get(str(name)) or speed_title(name) or str(name)


def scenario_rank(name: object) -> tuple:
    """Sort key of scenarios: the paper's A, B, C, then speed transfers by test speed (the
    within-speed arm first), then any other name."""
    if name in SCENARIO_TITLES:
        return (list(SCENARIO_TITLES).index(name),)
    parsed = parse_speed_scenario(name)
    if parsed is not None:
        train, test = parsed
        return (len(SCENARIO_TITLES), natural(test), train != (test,), natural("+".join(train)))
    return (len(SCENARIO_TITLES) + 1, natural(str(name)))


def _run_keys(run: RunResult) -> dict[str, object]:
    """The run's columns; ``unit`` is -1 (nominal profile) for runs labelled without one."""
    return {c: run.labels.get(c, -1) if c == "unit" else run.labels[c] for c in RUN_COLUMNS}


def tidy(runs: Iterable[RunResult]) -> tuple[pd.DataFrame, pd.DataFrame, pd.DataFrame]:
    """(results, per_class, confusion) long tables from run results."""
    rows, per_class, confusion = [], [], []
    for run in runs:
        keys = _run_keys(run)
        rows.append(
            {
                **keys,
                "macro_f1": run.macro_f1,
                "n_train": run.n_train,
                "n_test": run.n_test,
                "fit_seconds": run.fit_seconds,
                "status": run.status,
                "error": run.error,
                "train_sensor": run.labels.get("train_sensor", keys["sensor"]),
                "test_sensor": run.labels.get("test_sensor", keys["sensor"]),
                "node": run.labels.get("node"),
            }
        )
        per_class.extend({**keys, **entry} for entry in run.per_class)
        for i, true in enumerate(run.classes):
            for j, predicted in enumerate(run.classes):
                confusion.append(
                    {**keys, "true": true, "predicted": predicted, "count": run.confusion[i][j]}
                )
    results = pd.DataFrame(rows, columns=RESULT_COLUMNS)
    order = ["machine", "scenario", "sensor", "classifier", "unit", "repeat"]
    results = results.sort_values(order, ignore_index=True)
    return (
        results,
        pd.DataFrame(
            per_class, columns=[*RUN_COLUMNS, "class", "precision", "recall", "f1", "support"]
        ),
        pd.DataFrame(confusion, columns=[*RUN_COLUMNS, "true", "predicted", "count"]),
    )


_RECORDING_FIELDS = ("recording_id", "true", "predicted", "count")


def per_recording(runs: Iterable[RunResult]) -> pd.DataFrame:
    """Confusion counts per (run, test recording): run columns, recording_id, true,
    predicted, count (non-zero pairs only; empty for runs stored before it existed)."""
    rows = [[*_run_keys(run).values(), *entry] for run in runs for entry in run.per_recording]
    return pd.DataFrame(rows, columns=[*RUN_COLUMNS, *_RECORDING_FIELDS])


def write_frame(frame: pd.DataFrame, path: str | os.PathLike[str]) -> None:
    """Write a DataFrame atomically as Parquet or CSV (by suffix); a CSV's text cells
    spreadsheet-safe (:mod:`sdt_framework.csv_cells`: a condition ``=x`` is ``'=x``)."""
    path = Path(path)
    with atomic_path(path) as tmp:
        if path.suffix == ".parquet":
            frame.to_parquet(tmp, index=False)
        else:
            escape_frame(frame).to_csv(tmp, index=False)
