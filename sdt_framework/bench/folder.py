"""The results folder: recognised before it is written, resumed only by its own configuration.

An sdt results folder is recognised by its marker file ``.sdt-results.json``,
the first file a benchmark writes into a new folder. It records which
configuration the folder holds: every setting that changes a result (data,
names, windowing, scenarios, allocation, repetitions, seed), not the ones that
only change how the work is run (``jobs``, ``backend``, ``scheduler``,
``cache_dir``, ``report``). Folders written before the marker existed are
recognised by their ``config.toml`` header instead.

:func:`claim_results_folder` accepts a folder that does not exist or is
empty (and claims it), or an sdt results folder of the same configuration (a
resume). It refuses, with one line, a path that is a file, a folder that is
not an sdt results folder, a results folder holding files sdt did not write,
and a results folder of another configuration (naming what differs), so
nothing a user owns and no other benchmark's results are ever overwritten.
It then locks the folder for this process (:mod:`.folder_lock`): a second
benchmark started on the same folder while the first runs is refused, naming
the first one's process, instead of computing everything a second time.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

from ..errors import SDTError
from ..io import OutputError, atomic_write_text, ensure_writable_dir
from ..toml_files import parse_toml
from .config import BenchmarkConfig, write_config
from .config_paths import relative_to, resolve_written
from .folder_lock import LOCK, lock_results_folder

__all__ = [
    "MARKER",
    "OUTPUT_FILES",
    "RUN_ONLY_SETTINGS",
    "claim_results_folder",
    "config_identity",
]

MARKER = ".sdt-results.json"
_FORMAT = "sdt-framework benchmark results"
_CONFIG_HEADER = "# Resolved by sdt benchmark"

#: Every file `sdt benchmark` writes at the top of its folder (besides the marker and runs/).
OUTPUT_FILES = (
    "results.parquet",
    "results.csv",
    "per_class.parquet",
    "confusion.parquet",
    "per_recording.parquet",
    "allocation.csv",
    "skipped.csv",
    "features.parquet",
    "config.toml",
    "table4.md",
    "summary.json",
)
#: What `sdt report` adds to a results folder.
REPORT_ENTRIES = ("report.md", "report.html", "figures")
#: What `sdt explore` adds to the benchmark's folder (its sweep tables).
EXPLORE_FILES = (
    "explore.parquet",
    "points.csv",
    "skipped_points.csv",
    "main_effects.csv",
    "sensitivity.csv",
    "min_spec.csv",
    "min_spec_points.csv",
    "pareto.csv",
    "sweep.toml",
)
#: What the commands above the benchmark add to its folder: `sdt explore` and
#: `sdt compare` (comparison.csv, comparison_vs_<other>.csv).
DERIVED_ENTRIES = (*EXPLORE_FILES, "comparison.csv")
_DERIVED = re.compile(r"^comparison_vs_.+\.csv$")
#: Settings that change how a benchmark runs, never what it finds.
RUN_ONLY_SETTINGS = frozenset({"jobs", "backend", "scheduler", "cache_dir", "report"})
#: Settings that only grade what the runs found (the severity figures' zone tables, the
#: machines' bearings and speeds): changing them resumes the folder, and the next report
#: grades and draws by the new ones.
GRADING_SETTINGS = frozenset({"zones", "machine_specs"})
_OWN = frozenset({MARKER, LOCK, "runs", *OUTPUT_FILES, *REPORT_ENTRIES, *DERIVED_ENTRIES})
_TEMPORARY = re.compile(r"^\..+\.tmp$")  # left by an atomic write cut short (io.atomic_path)


def config_identity(config: BenchmarkConfig) -> dict[str, Any]:
    """The settings that define a benchmark's results (JSON-ready), paths as configured."""
    return config.model_dump(mode="json", exclude=set(RUN_ONLY_SETTINGS | GRADING_SETTINGS))


def _short(value: Any) -> str:
    text = json.dumps(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _differences(stored: dict[str, Any], current: dict[str, Any]) -> list[str]:
    names = sorted(set(stored) | set(current))
    return [
        f"{name}: {_short(stored.get(name))} -> {_short(current.get(name))}"
        for name in names
        if stored.get(name) != current.get(name)
    ]


def _stored_identity(out: Path) -> dict[str, Any] | None:
    """The identity recorded in ``out`` (marker, or legacy config.toml), None if not sdt's."""
    marker = out / MARKER
    if marker.is_file():
        try:
            data = json.loads(marker.read_bytes())
        except (OSError, ValueError):
            raise SDTError(
                f"{marker} is damaged, so the configuration of {out} is unknown; "
                f"choose a new --out folder"
            ) from None
        if not isinstance(data, dict) or data.get("format") != _FORMAT:
            raise SDTError(f"{marker} was not written by sdt; choose a new --out folder")
        identity = data.get("configuration")
        if not isinstance(identity, dict):
            return {}
        # version 2 stores paths relative to the folder; version 1 as given (absolute or
        # relative to the working directory of the run)
        return identity if data.get("version") == 2 else relative_to(identity, out)
    config = out / "config.toml"
    try:
        text = config.read_text(encoding="utf-8")
    except (OSError, ValueError):
        return None
    if not text.startswith(_CONFIG_HEADER):
        return None
    try:
        data = resolve_written(parse_toml(text, config).get("benchmark", {}), out)
        return relative_to(config_identity(BenchmarkConfig.model_validate(data)), out)
    except (SDTError, ValueError):  # not one sdt wrote as it reads it: not this folder's
        return None


def _describe(names: list[str]) -> str:
    shown = ", ".join(names[:3])
    return shown + (f" and {len(names) - 3} more" if len(names) > 3 else "")


def claim_results_folder(out: str | Path, config: BenchmarkConfig) -> bool:
    """Check ``out`` and claim it for ``config``; True when resuming an existing results folder.

    Writes the marker (first) and ``config.toml`` before any work, so an
    interrupted benchmark can always be resumed from its folder. The folder
    stays locked for this process until :func:`~.folder_lock.unlock_results_folder`
    or the process ends (a claim of a folder it holds already is a no-op lock).

    Raises
    ------
    SDTError
        For every folder that must not be written (see the module docstring), and
        a folder another running process holds.
    """
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise OutputError(
            f"--out {out} is a file; name a folder (new or empty, or a results folder to resume)"
        )
    entries = sorted(p.name for p in out.iterdir() if p.name != LOCK) if out.is_dir() else []
    current = relative_to(config_identity(config), out)  # moves with its data
    resuming = bool(entries)
    if resuming:
        stored = _stored_identity(out)
        if stored is None:
            raise SDTError(
                f"--out {out} is not an sdt results folder and not empty (it holds "
                f"{_describe(entries)}); choose a new or empty folder"
            )
        foreign = [
            n for n in entries if n not in _OWN and not (_TEMPORARY.match(n) or _DERIVED.match(n))
        ]
        if foreign:
            raise SDTError(
                f"--out {out} holds files sdt did not write ({_describe(foreign)}); "
                f"move them away or choose a new folder"
            )
        changed = _differences(stored, current)
        if changed:
            raise SDTError(
                f"--out {out} holds the results of another configuration "
                f"({'; '.join(changed[:3])}); resume it with `sdt benchmark "
                f"{out / 'config.toml'} --out {out}`, or choose a new --out folder"
            )
    ensure_writable_dir(out, "results folder", "--out")
    lock_results_folder(out)
    if not (out / MARKER).exists():
        atomic_write_text(
            out / MARKER, json.dumps({"format": _FORMAT, "version": 2, "configuration": current})
        )
    write_config(config, out / "config.toml")
    return resuming
