"""Finished runs on disk: one ``runs/<key>.json`` per successful run, for resuming.

A run file is written atomically once its run has finished with status "ok"
(failed and interrupted runs are never stored, so a resume retries them). On
resume every file is checked before it is trusted: a truncated file, a file
that is not JSON, a JSON document of another shape or one whose key does not
match its file name is named in a warning and ignored, and its run is
computed again (the fresh result then replaces the file).

A run file holds everything the output files need, so a resumed folder's
files equal an uninterrupted run's: scores, per-class table, confusion matrix
and the per-recording confusion counts (``per_recording``, which ``sdt
compare`` resamples). A file without the counts (written by a version that did
not store them) or whose counts do not add up to its test windows is
incomplete: it is ignored like a damaged one and its run computed again; such
old files are named in one warning, not one line each.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ..io import atomic_write_text
from .classify import RunResult
from .results import RUN_COLUMNS

__all__ = ["load_finished", "store_finished"]

Warn = Callable[[str], None]

#: field -> accepted JSON types of a stored run
_FIELDS: dict[str, tuple[type, ...]] = {
    "key": (str,),
    "labels": (dict,),
    "macro_f1": (float, int),
    "n_train": (int,),
    "n_test": (int,),
    "fit_seconds": (float, int),
    "status": (str,),
    "error": (str,),
    "per_class": (list,),
    "confusion": (list,),
    "classes": (list,),
    "per_recording": (list,),
}
#: the only missing field of a run file written before per-recording counts were stored
_OLD_FORMAT = "lacks field(s) ['per_recording']"


def _problem(data: Any, path: Path) -> str | None:
    """Why ``data`` (parsed from ``path``) is not a stored run, or None if it is one."""
    if not isinstance(data, dict):
        return f"a JSON {type(data).__name__}, not a run record"
    missing = sorted(set(_FIELDS) - set(data))
    if missing:
        return f"lacks field(s) {missing}"
    for name, types in _FIELDS.items():
        value = data[name]
        if not isinstance(value, types) or isinstance(value, bool):
            return f"field {name!r} has the wrong type ({type(value).__name__})"
    if data["key"] != path.stem:
        return f"holds run {str(data['key'])[:24]!r}, not the one its name says"
    if data["status"] != "ok":
        return f"status {str(data['status'])[:12]!r} (only finished runs are stored)"
    if set(RUN_COLUMNS) - {"unit"} - set(data["labels"]):  # unit: only with --units
        return "lacks run labels"
    if not math.isfinite(data["macro_f1"]) or not 0.0 <= data["macro_f1"] <= 1.0:
        return "macro_f1 is not a score between 0 and 1"
    return _recording_problem(data["per_recording"], data["n_test"])


def _recording_problem(rows: list[Any], n_test: int) -> str | None:
    """Why ``rows`` are not a run's per-recording counts of ``n_test`` test windows, or None."""
    shaped = all(
        isinstance(row, list)
        and len(row) == 4
        and all(isinstance(v, str) for v in row[:3])
        and isinstance(row[3], int)
        and not isinstance(row[3], bool)
        and row[3] > 0
        for row in rows
    )
    if not shaped:
        return "per_recording rows are not [recording, true, predicted, count]"
    total = sum(row[3] for row in rows)
    if total != n_test:
        return f"per_recording counts add up to {total}, not its {n_test} test windows"
    return None


def load_finished(runs_dir: Path, warn: Warn) -> dict[str, RunResult]:
    """The valid stored runs under ``runs_dir`` by key; every other file is warned about."""
    done: dict[str, RunResult] = {}
    old: list[Path] = []
    for path in sorted(runs_dir.glob("*.json")):
        try:
            data = json.loads(path.read_bytes())
        except (OSError, ValueError) as exc:  # unreadable, truncated, not UTF-8, not JSON
            reason = getattr(exc, "strerror", None) or "not a complete JSON document"
            warn(f"ignoring {path}: {reason}; its run will be computed again")
            continue
        problem = _problem(data, path)
        if problem == _OLD_FORMAT:
            old.append(path)
        elif problem:
            warn(f"ignoring {path}: {problem}; its run will be computed again")
        else:
            done[data["key"]] = RunResult(**{name: data[name] for name in _FIELDS})
    if old:
        warn(
            f"ignoring {len(old)} run file{'s' if len(old) > 1 else ''} in {runs_dir} written "
            f"without per-recording counts by an older version (e.g. {old[0].name}); "
            f"{'their runs' if len(old) > 1 else 'its run'} will be computed again"
        )
    return done


def store_finished(runs_dir: Path, result: RunResult) -> None:
    """Write one finished run atomically (complete or absent, never half-written)."""
    atomic_write_text(runs_dir / f"{result.key}.json", json.dumps(result.as_dict()))
