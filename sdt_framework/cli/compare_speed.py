"""``sdt compare``'s speed part: how much each sensor loses under a speed shift (text and JSON).

Shown when the folder holds speed-transfer arms (``--scenarios speed-transfer``);
the figures come from :mod:`~sdt_framework.verdict.speed_loss`.
"""

from __future__ import annotations

import json
from typing import Any

import numpy as np
from rich.table import Table

from .common import console, print_table

__all__ = ["print_speed_loss", "speed_loss_json", "speed_tables"]


def speed_tables(folder: Any, baseline: str) -> tuple[Any, Any, list[str]] | None:
    """(loss per sensor, loss per class, shift arms with no within-speed arm) of ``folder``;
    None when it has no speed-transfer arms."""
    from ..verdict import (
        recording_intervals,
        speed_arms,
        speed_loss,
        speed_loss_by_class,
        unpaired_arms,
    )

    results = folder.results
    if results is None:
        return None
    unpaired = unpaired_arms(results["scenario"])
    if not speed_arms(results["scenario"]) and not unpaired:
        return None
    per_class = folder.per_class
    by_class = None if per_class is None else speed_loss_by_class(per_class)
    loss = recording_intervals(speed_loss(results, baseline), folder.per_recording)
    return loss, by_class, unpaired


def _ci(low: float, high: float) -> str:
    return "" if np.isnan(low) else f" [{low:+.3f}, {high:+.3f}]"


def _cell(row: Any) -> str:
    """F1 within -> shifted, the loss with its interval, the excess over the baseline's."""
    text = f"{row.within_f1:.3f} -> {row.shift_f1:.3f}\nloss {row.loss:+.3f}"
    text += f"\nreps{_ci(row.loss_low, row.loss_high) or ' –'}"
    text += f"\nrecs{_ci(row.rec_low, row.rec_high) or ' –'}"
    if not np.isnan(row.excess):
        text += f"\nexcess {row.excess:+.3f}{_ci(row.excess_low, row.excess_high)}"
    return text


def print_speed_loss(tables: tuple[Any, Any, list[str]], baseline: str) -> None:
    """One table per machine: rows shift arm x classifier, a column per sensor (F1 within
    speed -> shifted, the loss and the excess over ``baseline``'s); then the loss per class."""
    from ..verdict import UNPAIRED

    loss, by_class, unpaired = tables
    if unpaired:
        console.print(f"speed transfer: {', '.join(unpaired)}: {UNPAIRED}", highlight=False)
    for machine, part in loss.groupby("machine", sort=False):
        sensors = list(dict.fromkeys([baseline, *part["sensor"]]))
        sensors = [s for s in sensors if s in set(part["sensor"])]
        out = Table(
            title=f"{machine}: Macro F1 under a speed shift (trained -> tested speeds), within "
            f"speed -> shifted on the same test runs; loss = within - shifted, 95 % CIs over "
            f"repetitions and over test recordings; excess = loss - {baseline}'s loss, 95 % CI "
            f"over repetitions",
            title_justify="left",
        )
        out.add_column("speeds", no_wrap=True)
        out.add_column("classifier", no_wrap=True)
        for sensor in sensors:
            out.add_column(str(sensor))
        previous = None
        for (shift, classifier), rows in part.groupby(["shift", "classifier"], sort=False):
            if previous is not None and shift != previous:
                out.add_section()
            by_sensor = {r.sensor: r for r in rows.itertuples()}
            out.add_row(
                shift.removeprefix("speed ") if shift != previous else "",
                str(classifier),
                *(_cell(by_sensor[s]) if s in by_sensor else "–" for s in sensors),
            )
            previous = shift
        print_table(out)
    if by_class is None or by_class.empty:
        return
    for (machine, shift), part in by_class.groupby(["machine", "shift"], sort=False):
        wide = part.pivot(index="sensor", columns="class", values="loss")
        out = Table(
            title=f"{machine}, {shift}: loss of F1 per class (within speed - shifted, mean "
            f"over classifiers and repetitions)",
            title_justify="left",
        )
        out.add_column("sensor", no_wrap=True)
        for name in wide.columns:
            out.add_column(str(name))
        sensors = [s for s in dict.fromkeys([baseline, *part["sensor"]]) if s in wide.index]
        for sensor in sensors:
            out.add_row(str(sensor), *(f"{v:+.3f}" for v in wide.loc[sensor]))
        print_table(out)


def speed_loss_json(tables: tuple[Any, Any, list[str]] | None) -> Any:
    """The ``speed_loss`` key of ``sdt compare --json``: None without speed-transfer arms."""
    if tables is None:
        return None
    loss, by_class, unpaired = tables
    return {
        "unpaired": unpaired,
        "per_sensor": json.loads(loss.to_json(orient="records")),
        "per_class": None if by_class is None else json.loads(by_class.to_json(orient="records")),
    }
