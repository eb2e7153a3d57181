"""The manifest reader: any recordings described by a CSV or Parquet table.

Columns (one row per file, or per variable/column of a file):

========================  =====================================================
path                      CSV, NPY or MAT file; relative to the manifest folder
sampling_rate_hz          rate of the stored samples, Hz
condition                 class label (``healthy``, ``bearing bpfo``, ...)
severity                  fault level (integer), empty for healthy
recording_id              the physical run: rows sharing it are one run
channel                   sensor position (``ch1``, ``pump-DE-h``, ...)
machine (optional)        default ``"machine"``
units (optional)          ``g`` (default), ``mg`` or ``m/s^2``
variable (optional)       CSV column name or MATLAB variable
speed (optional)          operating point label
========================  =====================================================

Rows sharing (recording_id, channel) are the acquisitions of one
:class:`Recording`, in manifest order. A missing file is reported in
``skipped`` with the manifest line; an unknown column or a bad value is an
:class:`SDTError` naming the field.
"""

from __future__ import annotations

import os
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from ..errors import SDTError
from .recording import DataFileError, Dataset, Recording, Skipped, measurement_groups
from .signal_files import read_signal, signal_shape

__all__ = ["REQUIRED", "UNITS_TO_G", "open_manifest"]

REQUIRED = ("path", "sampling_rate_hz", "condition", "severity", "recording_id", "channel")
OPTIONAL = ("machine", "units", "variable", "speed")
UNITS_TO_G = {"g": 1.0, "mg": 1e-3, "m/s^2": 1.0 / 9.80665}


def _read_table(path: Path) -> pd.DataFrame:
    if not path.is_file():
        raise SDTError(f"manifest {path} not found")
    suffix = path.suffix.lower()
    if suffix == ".csv":
        return pd.read_csv(path, dtype=str, keep_default_na=False)
    if suffix == ".parquet":
        return pd.read_parquet(path).astype(object).where(lambda d: d.notna(), "")
    raise SDTError(f"manifest {path}: unsupported type {suffix!r}; use .csv or .parquet")


def _cell(row: pd.Series, field: str) -> str:
    value = row.get(field, "")
    return "" if value is None else str(value).strip()


def _row_fields(manifest: Path, line: int, row: pd.Series) -> dict[str, Any]:
    where = f"manifest {manifest} line {line}"
    for field in ("path", "condition", "recording_id", "channel"):
        if not _cell(row, field):
            raise SDTError(
                f"{where}: field 'path'/'condition'/'recording_id'/'channel' "
                f"must not be empty (field {field!r} is)"
            )
    try:
        rate = float(_cell(row, "sampling_rate_hz"))
        if not (np.isfinite(rate) and rate > 0):
            raise ValueError
    except ValueError:
        raise SDTError(
            f"{where}: field 'sampling_rate_hz' = {_cell(row, 'sampling_rate_hz')!r} "
            f"is not a positive number"
        ) from None
    text = _cell(row, "severity")
    try:
        severity = int(float(text)) if text and text.lower() != "nan" else None
    except ValueError:
        raise SDTError(f"{where}: field 'severity' = {text!r} is not an integer") from None
    units = _cell(row, "units") or "g"
    if units not in UNITS_TO_G:
        raise SDTError(f"{where}: field 'units' = {units!r}; use one of {', '.join(UNITS_TO_G)}")
    file = Path(_cell(row, "path")).expanduser()
    return {
        "file": file if file.is_absolute() else manifest.parent / file,
        "rate": rate,
        "severity": severity,
        "units": units,
        "variable": _cell(row, "variable") or None,
        "machine": _cell(row, "machine") or "machine",
        "speed": _cell(row, "speed") or None,
        "condition": _cell(row, "condition"),
        "run": _cell(row, "recording_id"),
        "channel": _cell(row, "channel"),
        "line": line,
    }


def open_manifest(
    path: str | os.PathLike[str], *, name: str = "manifest", validate: bool = False
) -> Dataset:
    """Open a manifest file; see the module docstring for its columns.

    Parameters
    ----------
    path
        ``.csv`` or ``.parquet`` manifest.
    validate
        Read every signal now so that bad files land in ``skipped``.
    """
    manifest = Path(path).expanduser()
    table = _read_table(manifest)
    columns = [str(c) for c in table.columns]
    unknown = sorted(set(columns) - set(REQUIRED) - set(OPTIONAL))
    if unknown:
        raise SDTError(
            f"manifest {manifest}: unknown column(s) {', '.join(map(repr, unknown))}; "
            f"allowed: {', '.join(REQUIRED + OPTIONAL)}"
        )
    missing = [c for c in REQUIRED if c not in columns]
    if missing:
        raise SDTError(
            f"manifest {manifest}: missing required column(s) {', '.join(map(repr, missing))}"
        )
    groups: dict[tuple[str, str, str], list[dict[str, Any]]] = {}
    skipped: list[Skipped] = []
    for index, row in table.iterrows():
        fields = _row_fields(manifest, int(index) + 2, row)
        if not fields["file"].is_file():
            skipped.append(
                Skipped(
                    str(fields["file"]),
                    f"file not found (manifest {manifest} line {fields['line']})",
                )
            )
            continue
        try:
            fields["shape"] = signal_shape(fields["file"], fields["variable"])
        except DataFileError as exc:
            skipped.append(Skipped(str(fields["file"]), f"{exc} (manifest line {fields['line']})"))
            continue
        key = (fields["machine"], fields["run"], fields["channel"])
        groups.setdefault(key, []).append(fields)
    recordings = []
    for (machine, run, channel), rows in groups.items():
        first = rows[0]
        lengths = {r["shape"][1] for r in rows}
        meta = {k: {r[k] for r in rows} for k in ("rate", "condition", "severity", "speed")}
        conflict = [k for k, v in meta.items() if len(v) > 1]
        if len(lengths) > 1 or conflict:
            what = ", ".join(conflict) or f"acquisition lengths {sorted(lengths)}"
            lines = ", ".join(str(r["line"]) for r in rows)
            skipped.append(
                Skipped(
                    str(first["file"]),
                    f"recording {run!r} channel {channel!r}: "
                    f"rows disagree on {what} (manifest lines {lines})",
                )
            )
            continue
        n_acq = sum(r["shape"][0] for r in rows)
        recordings.append(
            Recording(
                dataset=name,
                machine=machine,
                speed=first["speed"],
                condition=first["condition"],
                severity=first["severity"],
                run=run,
                channel=channel,
                recording_id=f"{run}/{channel}",
                sampling_rate_hz=first["rate"],
                units=first["units"],
                n_acquisitions=n_acq,
                samples_per_acquisition=lengths.pop(),
                measurement=measurement_groups(n_acq),
                source=str(first["file"]),
                reader=partial(
                    _load_rows, tuple((r["file"], r["variable"], r["units"]) for r in rows)
                ),
            )
        )
    dataset = Dataset(name, recordings, skipped)
    if validate:
        dataset.validate()
    return dataset


def _load_rows(rows: tuple[tuple[Path, str | None, str], ...]) -> np.ndarray:
    parts = [read_signal(file, variable) * UNITS_TO_G[units] for file, variable, units in rows]
    return np.concatenate(parts, axis=0)
