"""Two results folders compared with each other: what each is called and what pairs their runs.

``sdt compare A B`` (two feature sets, two feature dtypes, two datasets of
the same machines) compares the folders, not the sensors: a run of A is paired
with the run of B of the same machine, scenario, sensor, classifier and
repetition, and the folder is the treatment (column "source"). Each folder is
named by what differs between them: its feature set, else its dataset, else
its folder name, else its whole path. Nothing here reads a file: the caller
hands the tables over (``report.load_results`` reads a folder).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from ..errors import SDTError
from .compare import Comparison, compare, stack_folders

__all__ = ["FOLDER_CELLS", "FolderPair", "folder_labels", "pair_folders"]

#: what two paired runs of two folders share besides the repetition
FOLDER_CELLS = ("machine", "scenario", "sensor", "classifier")


@dataclass(frozen=True)
class FolderPair:
    """Two folders' runs as one table, each run under its folder's label ("source")."""

    labels: tuple[str, str]
    results: pd.DataFrame
    #: both folders' per-recording counts (the recording intervals), None unless both have them
    per_recording: pd.DataFrame | None
    baseline: str
    #: the first folder's allocation (the test runs per class)
    allocation: pd.DataFrame | None
    #: the comparison table's file name, ``comparison_vs_<first folder>.csv`` (in the second)
    table_name: str

    def compare(self, margin: float = 0.02) -> Comparison:
        """The paired comparison of the other folder with the baseline folder."""
        return compare(
            self.results,
            self.baseline,
            margin=margin,
            treatment="source",
            cells=list(FOLDER_CELLS),
            per_recording=self.per_recording,
            allocation=self.allocation,
        )


def folder_labels(results: Sequence[pd.DataFrame], paths: Sequence[Path]) -> list[str]:
    """Each folder's name by what differs: feature set, dataset, folder name, else whole path."""
    for column in ("feature_set", "dataset"):
        values = [sorted(frame[column].dropna().unique()) for frame in results]
        if all(len(v) == 1 for v in values) and values[0] != values[1]:
            return [str(v[0]) for v in values]
    names = [Path(p).name for p in paths]
    return names if names[0] != names[1] else [str(p) for p in paths]


def pair_folders(
    results: Sequence[pd.DataFrame],
    paths: Sequence[Path],
    *,
    per_recording: Sequence[pd.DataFrame | None] = (None, None),
    allocation: pd.DataFrame | None = None,
    baseline: str | None = None,
) -> FolderPair:
    """Two folders' tables (``results.parquet``, optionally ``per_recording.parquet``) as a pair.

    ``baseline`` is one folder's label (default: the first folder's).

    Raises
    ------
    SDTError
        Not two folders, or a baseline that is neither folder's label.
    """
    if len(results) != 2 or len(paths) != 2 or len(per_recording) != 2:
        raise SDTError(f"a pair is two folders, got {len(paths)}")
    labels = folder_labels(results, paths)
    if baseline is not None and baseline not in labels:
        raise SDTError(f"with two folders --baseline must be one of {labels}, got {baseline!r}")
    both = per_recording[0] is not None and per_recording[1] is not None
    return FolderPair(
        labels=(labels[0], labels[1]),
        results=stack_folders(results, labels),
        per_recording=stack_folders(per_recording, labels) if both else None,
        baseline=baseline or labels[0],
        allocation=allocation,
        table_name=f"comparison_vs_{Path(paths[0]).name}.csv",
    )
