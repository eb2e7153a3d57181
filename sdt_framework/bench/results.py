"""Tidy result tables and the paper's Table 4 pivot, written atomically.

``results`` has one row per run (dataset, machine, scenario, sensor,
feature_set, classifier, repeat, unit (-1: the nominal profile), seed,
macro_f1, n_train, n_test, fit_seconds, status, error, and what it trained
and tested on: train_sensor, test_sensor, node; ``sensor`` is the row's
label: the sensor, ``TRAIN -> TEST`` for a transfer, ``... @ NODE`` for a
node); ``per_class``,
``confusion`` and ``per_recording`` (confusion counts per test recording) are
long tables keyed by the same run columns. ``table4`` is mean +/- SD (sample
SD, ddof=1) of Macro F1 with scenario blocks, sensor rows and machine x
classifier columns.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator, Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from ..io import atomic_path, atomic_write_text
from .classify import RunResult

__all__ = [
    "RUN_COLUMNS",
    "SCENARIO_TITLES",
    "per_recording",
    "table4",
    "table4_blocks",
    "table4_markdown",
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


def table4(results: pd.DataFrame) -> pd.DataFrame:
    """Mean and SD of Macro F1 per (scenario, sensor) x (machine, classifier).

    Returns a frame indexed by (scenario, sensor) with a column MultiIndex
    (machine, classifier, stat) where stat is "mean", "sd" or "n".
    """
    ok = results[results["status"] == "ok"]
    grouped = ok.groupby(["scenario", "sensor", "machine", "classifier"])["macro_f1"]
    stats = pd.DataFrame({"mean": grouped.mean(), "sd": grouped.std(ddof=1), "n": grouped.count()})
    wide = stats.unstack(["machine", "classifier"])
    wide = wide.reorder_levels([1, 2, 0], axis=1).sort_index(axis=1)
    scenario_order = {s: i for i, s in enumerate(SCENARIO_TITLES)}
    return wide.sort_index(
        key=lambda idx: (
            idx.map(lambda v: scenario_order.get(v, 99)) if idx.name == "scenario" else idx
        )
    )


def table4_blocks(
    wide: pd.DataFrame, sensor_order: Sequence[str] = ()
) -> Iterator[tuple[str, pd.DataFrame, list[str]]]:
    """(scenario, its block of ``table4(...)``, sensors in display order) per scenario.

    Scenarios come in the paper's order (A, B, C); sensors in ``sensor_order``
    first, then any others in the block. Every view of Table 4 (Markdown,
    terminal, report deltas) walks the table through this one function.
    """
    present = set(wide.index.get_level_values(0))
    for scenario in [s for s in SCENARIO_TITLES if s in present]:
        block = wide.loc[scenario]
        sensors = [s for s in sensor_order if s in block.index]
        sensors += [s for s in block.index if s not in sensors]
        yield scenario, block, sensors


def _cell(mean: float, sd: float, n: float) -> str:
    if np.isnan(mean):
        return "–"
    if n < 2 or np.isnan(sd):
        return f"{mean:.4f}"
    return f"{mean:.4f} ± {sd:.4f}"


def table4_markdown(results: pd.DataFrame, sensor_order: list[str] | None = None) -> str:
    """The Table 4 layout as Markdown: one block per scenario, best mean per column in bold."""
    wide = table4(results)
    if wide.empty:
        return "_No successful runs: nothing to tabulate._\n"
    columns = sorted({(m, c) for m, c, _ in wide.columns})
    header = "| Sensor | " + " | ".join(f"{m} {c.upper()}" for m, c in columns) + " |"
    lines = [header, "|---|" + "---|" * len(columns)]
    for scenario, block, sensors in table4_blocks(wide, sensor_order or ()):
        lines.append(f"| **{SCENARIO_TITLES[scenario]}** |" + " |" * len(columns))
        best = {col: block[(*col, "mean")].max() for col in columns}
        for sensor in sensors:
            cells = []
            for col in columns:
                mean, sd, n = (block.loc[sensor, (*col, s)] for s in ("mean", "sd", "n"))
                text = _cell(mean, sd, n)
                cells.append(f"**{text}**" if not np.isnan(mean) and mean == best[col] else text)
            lines.append(f"| {sensor} | " + " | ".join(cells) + " |")
    note = "\nMacro F1, mean ± SD (sample SD over repetitions); best mean per column in bold.\n"
    return "\n".join(lines) + "\n" + note


def write_frame(frame: pd.DataFrame, path: str | os.PathLike[str]) -> None:
    """Write a DataFrame atomically as Parquet or CSV (by suffix)."""
    path = Path(path)
    with atomic_path(path) as tmp:
        if path.suffix == ".parquet":
            frame.to_parquet(tmp, index=False)
        else:
            frame.to_csv(tmp, index=False)


def write_markdown(text: str, path: str | os.PathLike[str]) -> None:
    """Write a Markdown file atomically."""
    atomic_write_text(path, text)
