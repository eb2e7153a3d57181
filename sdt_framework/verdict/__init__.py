"""The engineer's verdict: paired statistics between sensors, equivalence, ranking.

Pure functions on the tidy results table (and the per-recording confusion
counts), above ``bench`` results and below ``report`` and the CLI: nothing
here reads or writes files, so the same numbers feed ``sdt compare``, the
report's verdict section and a user's notebook. Its one figure, the
critical-difference diagram, is drawn here (``cdplot.py``), as every package
draws the figures of its own results (see :mod:`sdt_framework.report`).

Public API
----------
compare(results, baseline, *, margin=0.02, ...) -> Comparison
    Paired differences per cell, per machine and scenario and overall, with
    repetition and recording intervals, Holm-adjusted p-values, TOST and labels.
pair_folders(results, paths, *, per_recording, allocation, baseline) -> FolderPair
    Two results folders' tables paired run by run, each folder named by what
    differs (feature set, dataset, folder name); ``FolderPair.compare(margin)``.
stack_folders(frames, labels)
    Two results tables as one, to compare two folders ("source" as treatment).
verdict(comparison) -> list[Finding]
    Plain sentences, each citing its numbers.
speed_arms, speed_loss, speed_loss_by_class, unpaired_arms, UNPAIRED ; recording_intervals
    The loss of Macro F1 under a speed shift (speed-transfer arms, issue 43), per
    sensor and per class, with intervals over repetitions and over test recordings.
friedman_nemenyi(scores) -> Ranking ; plot_cd_diagram(ranking)
    Friedman test, Nemenyi post-hoc, critical difference and its diagram.
"""

from __future__ import annotations

from .cdplot import plot_cd_diagram
from .compare import CELL_KEYS, Comparison, compare, stack_folders
from .equivalence import LABELS, interval_label
from .folders import FOLDER_CELLS, FolderPair, folder_labels, pair_folders
from .ranking import Ranking, critical_difference, friedman_nemenyi, q_alpha
from .recordings import macro_f1
from .sentences import Finding, verdict
from .speed_loss import UNPAIRED, speed_arms, speed_loss, speed_loss_by_class, unpaired_arms
from .speed_recordings import recording_intervals

__all__ = [
    "CELL_KEYS",
    "FOLDER_CELLS",
    "LABELS",
    "UNPAIRED",
    "Comparison",
    "Finding",
    "FolderPair",
    "Ranking",
    "compare",
    "critical_difference",
    "folder_labels",
    "friedman_nemenyi",
    "interval_label",
    "macro_f1",
    "pair_folders",
    "plot_cd_diagram",
    "q_alpha",
    "recording_intervals",
    "speed_arms",
    "speed_loss",
    "speed_loss_by_class",
    "stack_folders",
    "unpaired_arms",
    "verdict",
]
