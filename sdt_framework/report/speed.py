"""The report's "Speed transfer" section: how much each sensor loses under a speed shift.

Shown when the folder holds speed-transfer arms (``--scenarios speed-transfer``):
per machine, each shift arm's loss of Macro F1 per sensor and classifier (within
speed minus shifted, paired on the same test runs, with the excess over the
reference's loss), then the loss of F1 per class and sensor
(:mod:`~sdt_framework.verdict.speed_loss`).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ..verdict.speed_loss import (
    UNPAIRED,
    speed_arms,
    speed_loss,
    speed_loss_by_class,
    unpaired_arms,
)
from ..verdict.speed_recordings import recording_intervals
from .document import Block, Heading, Paragraph, Table, literal
from .load import ResultsFolder

__all__ = ["speed_blocks"]

INTRO = (
    "Each fold tested at a speed T is scored twice on the same test runs: trained at T "
    "(within speed) and trained at the other speeds S (shifted, `S -> T`). The loss is "
    "within minus shifted, run by run (same sensor, classifier, unit and repetition); "
    "positive: the classifier does worse at a speed it was not trained at. The excess is a "
    "sensor's loss minus the reference's: a candidate that loses more than the reference "
    "under the same shift has a positive excess. Intervals: 95 % Student-t over repetitions, "
    "and for the loss also over test recordings (resampled within each class, one draw for "
    "both arms; '–' where a class has one test recording)."
)


def _ci(mean: float, low: float, high: float) -> str:
    if np.isnan(mean):
        return "–"
    return f"{mean:+.3f}" + ("" if np.isnan(low) else f" [{low:+.3f}, {high:+.3f}]")


def _loss_table(loss: pd.DataFrame) -> Table:
    rows: list[tuple[str, ...]] = []
    for shift, part in loss.groupby("shift", sort=False):
        rows.append((f"**{literal(shift)}**",) + ("",) * 6)
        for r in part.itertuples():
            rows.append(
                (
                    literal(r.sensor),
                    literal(r.classifier),
                    f"{r.within_f1:.3f}",
                    f"{r.shift_f1:.3f}",
                    _ci(r.loss, r.loss_low, r.loss_high),
                    _ci(r.loss, r.rec_low, r.rec_high).partition(" ")[2] or "–",
                    _ci(r.excess, r.excess_low, r.excess_high),
                )
            )
    header = ("sensor", "classifier", "within speed", "shifted", "loss [reps CI]",
              "recordings CI", "excess [reps CI]")  # fmt: skip
    return Table(header, tuple(rows), "Macro F1, mean over repetitions.")


def _class_table(by_class: pd.DataFrame, first: str) -> Table:
    classes = list(dict.fromkeys(by_class["class"]))
    rows: list[tuple[str, ...]] = []
    for shift, part in by_class.groupby("shift", sort=False):
        rows.append((f"**{literal(shift)}**",) + ("",) * len(classes))
        wide = part.pivot(index="sensor", columns="class", values="loss")
        for sensor in dict.fromkeys([first, *part["sensor"]]):
            if sensor not in wide.index:
                continue
            cells = [wide.loc[sensor].get(c, np.nan) for c in classes]
            rows.append((literal(sensor), *("–" if np.isnan(v) else f"{v:+.3f}" for v in cells)))
    header = ("sensor", *(literal(c) for c in classes))
    note = "Loss of the class's F1 (within speed - shifted), mean over classifiers and repetitions."
    return Table(header, tuple(rows), note)


def speed_blocks(folder: ResultsFolder) -> list[Block]:
    """The section; empty when the folder has no speed-transfer arm."""
    results = folder.results
    unpaired = [] if results is None else unpaired_arms(results["scenario"])
    if results is None or (not speed_arms(results["scenario"]) and not unpaired):
        return []
    loss = recording_intervals(speed_loss(results, folder.reference), folder.per_recording)
    blocks: list[Block] = [Heading("Speed transfer: the loss under a speed shift", 2)]
    blocks.append(Paragraph(INTRO))
    if unpaired:
        blocks.append(Paragraph(f"{literal(', '.join(unpaired))}: {UNPAIRED}."))
    for machine, part in loss.groupby("machine", sort=False):
        blocks += [Heading(f"{literal(machine)}: per sensor", 3), _loss_table(part)]
    if folder.per_class is not None:
        by_class = speed_loss_by_class(folder.per_class)
        for machine, part in by_class.groupby("machine", sort=False):
            blocks += [
                Heading(f"{literal(machine)}: per class", 3),
                _class_table(part, folder.reference),
            ]
    return blocks
