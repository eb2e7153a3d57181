"""Everything a benchmark leaves in its output folder, each file written atomically.

results.parquet / results.csv   one row per run (tidy)
per_class.parquet               precision, recall, F1, support per class per run
confusion.parquet               confusion-matrix counts per run (long form)
per_recording.parquet           confusion counts per run and test recording (for sdt compare)
allocation.csv                  the train/test allocation used
skipped.csv                     (machine, scenario) pairs that could not be scored and
                                sensors the data cannot simulate ("all" in the other
                                columns), and why
features.parquet                repetition-0 features of every window, per sensor (for plots)
config.toml                     the fully resolved, re-runnable configuration
table4.md                       the paper's Table 4 layout, mean +/- SD Macro F1
summary.json                    counts, timings, software versions
"""

from __future__ import annotations

import json
import os
import platform
from importlib import metadata
from pathlib import Path

import pandas as pd

from ..io import atomic_write_text
from .config import write_config
from .folder import OUTPUT_FILES
from .results import per_recording, tidy, write_frame
from .runner import BenchmarkResult
from .saturation import saturation_summary
from .table4 import build_table4, table4_markdown

__all__ = ["OUTPUT_FILES", "software_versions", "write_outputs"]

_PACKAGES = (
    "sdt-framework",
    "numpy",
    "scipy",
    "pandas",
    "pyarrow",
    "scikit-learn",
    "xgboost",
    "pydantic",
    "pluggy",
    "joblib",
    "distributed",
    "matplotlib",
)


def software_versions() -> dict[str, str]:
    """Python and key package versions, for provenance (shared with the report)."""
    versions = {"python": platform.python_version()}
    for name in _PACKAGES:
        try:
            versions[name] = metadata.version(name)
        except metadata.PackageNotFoundError:
            versions[name] = "not installed"
    return versions


def _under_data_root(path: str, data: str | None) -> str:
    """``path`` relative to the data root (the manifest's folder, or the data folder)."""
    if data is None or not os.path.isabs(path):
        return path
    root = os.path.abspath(data if os.path.isdir(data) else os.path.dirname(data) or ".")
    inside = os.path.commonpath([root, os.path.abspath(path)]) == root
    return os.path.relpath(path, root) if inside else path


def write_outputs(result: BenchmarkResult, out_dir: str | Path) -> pd.DataFrame:
    """Write every output file; return the tidy results table."""
    out = Path(out_dir)
    plan = result.plan
    results, per_class, confusion = tidy(result.runs)
    write_frame(results, out / "results.parquet")
    write_frame(results, out / "results.csv")
    write_frame(per_class, out / "per_class.parquet")
    write_frame(confusion, out / "confusion.parquet")
    write_frame(per_recording(result.runs), out / "per_recording.parquet")
    write_frame(plan.allocation, out / "allocation.csv")
    skipped = pd.DataFrame(
        [(m, s, "all", reason) for (m, s), reason in sorted(plan.skipped.items())]
        + [("all", "all", name, reason) for name, reason in plan.skipped_sensors.items()],
        columns=["machine", "scenario", "sensor", "reason"],
    )
    write_frame(skipped, out / "skipped.csv")
    write_frame(result.features[result.features["repeat"] == 0], out / "features.parquet")
    write_config(plan.config, out / "config.toml")
    atomic_write_text(
        out / "table4.md",
        "# Table 4: Macro F1 by scenario, sensor, machine and "
        "classifier\n\n" + table4_markdown(build_table4(results, [s.name for s in plan.sensors])),
    )
    summary = {
        "dataset": plan.dataset.name,
        "recordings": len(plan.recordings),
        "runs": len(results),
        "runs_ok": int((results["status"] == "ok").sum()),
        "runs_failed": int((results["status"] == "error").sum()),
        "runs_computed": result.runs_computed,
        "runs_resumed": result.runs_resumed,
        "feature_blocks_computed": result.features_computed,
        "feature_blocks_cached": result.features_cached,
        "skipped": [
            {"machine": m, "scenario": s, "reason": r} for (m, s), r in sorted(plan.skipped.items())
        ],
        "skipped_sensors": [
            {"sensor": name, "reason": reason} for name, reason in plan.skipped_sensors.items()
        ],
        "reference": plan.reference,
        "dataset_skipped": [
            {**s.as_dict(), "path": _under_data_root(s.path, plan.config.data)}
            for s in plan.dataset.skipped
        ],
        "seconds": result.seconds,
        "saturation": saturation_summary(result.saturation)
        if result.saturation is not None
        else {},
        "software": software_versions(),
        # details of the machine that ran it: here only, never in the shareable report
        "machine": {
            "platform": platform.platform(),
            "processors": os.cpu_count(),
            "cache_dir": result.cache_dir,
        },
    }
    atomic_write_text(out / "summary.json", json.dumps(summary, indent=2))
    return results
