"""Read a benchmark results folder, tolerating missing or broken optional files.

Only ``results.parquet`` (or ``results.csv``) is required: without it there is
nothing to report, and that is one clear :class:`~sdt_framework.errors.SDTError`
naming the path. Every other file may be missing or unreadable; it is then
``None`` here and listed in :attr:`ResultsFolder.problems`, so the report can
say what it could not show instead of crashing.

``per_recording.parquet`` is also checked against the results: counts missing
for some runs (or not adding up to their test windows) would silently change
the verdict's labels, so such a file is set aside like an unreadable one and
:attr:`ResultsFolder.per_recording_problem` says why (``sdt compare`` then
refuses the folder; the report lists the problem and compares on repetitions).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from ..bench.config import BenchmarkConfig, load_config
from ..csv_cells import unescape_frame
from ..errors import SDTError, one_line
from ..verdict.inputs import recording_gaps

__all__ = ["ResultsFolder", "load_results"]


@dataclass
class ResultsFolder:
    """The contents of one results folder; optional parts are None when absent."""

    path: Path
    results: pd.DataFrame
    per_class: pd.DataFrame | None = None
    confusion: pd.DataFrame | None = None
    per_recording: pd.DataFrame | None = None
    allocation: pd.DataFrame | None = None
    skipped: pd.DataFrame | None = None
    features: pd.DataFrame | None = None
    config: BenchmarkConfig | None = None
    config_text: str | None = None
    summary: dict[str, Any] | None = None
    problems: list[str] = field(default_factory=list)
    #: why per_recording.parquet was set aside (unreadable, or not matching the results)
    per_recording_problem: str | None = None
    #: the verdict's comparison per margin, computed once for every section that shows it
    comparisons: dict[float, Any] = field(default_factory=dict, repr=False)
    #: the severity package's zone agreement (or the SDTError saying why none), computed once
    agreement: Any = field(default=None, repr=False)
    #: the machines of the benchmark's dataset and config (:mod:`.machines`), read once
    machines: Any = field(default=None, repr=False)

    @property
    def ok(self) -> pd.DataFrame:
        """Successful runs only."""
        return self.results[self.results["status"] == "ok"]

    @property
    def failed(self) -> pd.DataFrame:
        """Failed runs (status ``error``) with their error messages."""
        return self.results[self.results["status"] != "ok"]

    @property
    def reference(self) -> str:
        """The reference sensor: config ``reference``, else the one the benchmark picked."""
        if self.config is not None and self.config.reference:
            return self.config.reference
        if self.summary and self.summary.get("reference"):
            return str(self.summary["reference"])
        present = set(self.results["sensor"].dropna())
        return "native-reference" if "native-reference" in present else "wilcoxon-786b10"

    @property
    def sensors(self) -> list[str]:
        """Sensor names in configuration order, then any others found in the results."""
        present = list(self.results["sensor"].dropna().unique())
        listed = list(self.config.sensors or []) if self.config is not None else []
        listed = [s for s in listed if s in present]  # a part's name becomes its canonical form
        found = [s for s in present if s not in listed]
        ordered = listed + sorted(found)
        if self.reference in ordered:  # the reference first, like the paper's tables
            ordered.remove(self.reference)
            ordered.insert(0, self.reference)
        return ordered


def _read(path: Path) -> pd.DataFrame:
    if path.suffix == ".parquet":
        return pd.read_parquet(path)
    return unescape_frame(pd.read_csv(path))  # labels as written: '=x is =x


def _check_per_recording(folder: ResultsFolder) -> None:
    """Set per_recording.parquet aside when it does not cover exactly the folder's runs."""
    if folder.per_recording is None:
        return
    gap = recording_gaps(folder.results, folder.per_recording)
    if gap is None:
        return
    folder.per_recording = None
    folder.per_recording_problem = f"{folder.path / 'per_recording.parquet'} {gap}"
    folder.problems.append(
        f"per_recording.parquet {gap}; the verdict uses the repetition intervals only"
    )


def load_results(results_dir: str | os.PathLike[str]) -> ResultsFolder:
    """Load the results folder ``results_dir``.

    Raises
    ------
    SDTError
        When ``results_dir`` is not a folder or holds no readable results table.
    """
    root = Path(results_dir)
    if not root.is_dir():
        raise SDTError(f"{root}: not a results folder (no such directory)")
    names = ("results.parquet", "results.csv")
    table = next((root / n for n in names if (root / n).is_file()), None)
    if table is None:
        raise SDTError(f"{root}: no results.parquet or results.csv; run `sdt benchmark` first")
    try:
        results = _read(table)
    except Exception as exc:  # any reader failure is the same user error
        raise SDTError(f"{table}: cannot read the results table: {exc}") from None
    if not {"machine", "scenario", "sensor", "classifier", "macro_f1", "status"} <= set(results):
        raise SDTError(f"{table}: not a benchmark results table (columns {list(results)})")
    if "error" not in results:
        results["error"] = None
    folder = ResultsFolder(root, results)
    for attr, name in (
        ("per_class", "per_class.parquet"),
        ("confusion", "confusion.parquet"),
        ("per_recording", "per_recording.parquet"),
        ("allocation", "allocation.csv"),
        ("skipped", "skipped.csv"),
        ("features", "features.parquet"),
    ):
        path = root / name
        if not path.is_file():
            folder.problems.append(f"{name} is missing")
            continue
        try:
            setattr(folder, attr, _read(path))
        except Exception as exc:  # reported; the rest of the report goes on
            folder.problems.append(f"{name} could not be read: {exc}")
            if attr == "per_recording":
                folder.per_recording_problem = f"{path} cannot be read ({one_line(exc, 160)})"
    _check_per_recording(folder)
    config_path = root / "config.toml"
    if config_path.is_file():
        folder.config_text = config_path.read_text(encoding="utf-8")
        try:
            folder.config = load_config(config_path, {})
        except SDTError as exc:
            folder.problems.append(f"config.toml is not a valid configuration: {exc}")
    else:
        folder.problems.append("config.toml is missing")
    summary_path = root / "summary.json"
    if summary_path.is_file():
        try:
            folder.summary = json.loads(summary_path.read_text(encoding="utf-8"))
        except ValueError as exc:
            folder.problems.append(f"summary.json could not be read: {exc}")
    else:
        folder.problems.append("summary.json is missing")
    return folder
