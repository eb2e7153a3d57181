"""The manifest reader: any recordings described by a CSV or Parquet table.

Columns (one row per file, or per variable/column of a file):

========================  =====================================================
path                      a signal file any registered reader reads (CSV, NPY,
                          MAT, IDE, TDMS, UFF58, WAV, LVM); relative to the
                          manifest folder
sampling_rate_hz          rate of the stored samples, Hz; may be empty where
                          the file holds its rate
condition                 class label (``healthy``, ``bearing bpfo``, ...)
severity                  fault level (integer), empty for healthy
recording_id              the physical run: rows sharing it are one run
channel                   sensor position (``ch1``, ``pump-DE-h``, ...)
machine (optional)        default ``"machine"``
units (optional)          ``g`` (default), ``mg`` or ``m/s^2``
variable (optional)       the signal in the file (CSV column, MATLAB variable,
                          TDMS ``GROUP/CHANNEL``, UFF58 number, WAV ``chN``,
                          LVM channel, IDE ``CHANNEL:AXIS``) as the file names
                          it, spaces included (:func:`.manifest_files.probe_row`)
speed (optional)          operating point label (a name: ``50``, ``full load``)
speed_rpm (optional)      shaft speed of the row, rpm (a positive number; empty:
                          not known, the spectrum may give an estimate)
full_scale_g (optional)   a reader's option: g at full scale of an integer WAV
========================  =====================================================

A file's rate and units, where it holds them, must agree with the row's
(:mod:`.manifest_files`); an empty field takes the file's. A ``machines.toml``
beside the manifest describes its machines (shaft speed, bearings, zone table:
:mod:`sdt_framework.machine_files`), so severity and the report can read them.

Rows sharing (machine, recording_id, channel) are the acquisitions of one
:class:`Recording`, in manifest order; its ``recording_id`` is
``machine/recording_id/channel``, so two machines may reuse run names (as
NLN-EMP does: ``healthy 1`` exists on every motor) and both are read, each as
its own recording. A missing or unreadable file is reported in ``skipped``
with the manifest line; an unknown column, a bad value (a severity of 1.7),
an exact duplicate row or a signal listed twice is an :class:`SDTError`
naming the lines (:mod:`.manifest_checks`): counting the same samples twice
would leak them across a train/test split.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import replace
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SDTError
from ..inputs import not_regular
from ..machine_files import MACHINE_FILE, load_machine_file
from ..signals.tokens import quote
from ..units import TO_G
from .manifest_checks import refuse_identical, refuse_shared_ids, refuse_signal_twice
from .manifest_files import probe_row, reconcile
from .manifest_table import ManifestRow, read_manifest_rows
from .manifest_values import severity_cell, speed_fields, speed_rpm_cell
from .recording import (
    DataFileError,
    Dataset,
    Recording,
    SignalTypeError,
    Skipped,
    measurement_groups,
)

__all__ = ["REQUIRED", "UNITS_TO_G", "open_manifest"]

REQUIRED = ("path", "sampling_rate_hz", "condition", "severity", "recording_id", "channel")
OPTIONAL = ("machine", "units", "variable", "speed", "speed_rpm", "full_scale_g")
UNITS_TO_G = TO_G  # the one table (sdt_framework.units)


def _cell(row: ManifestRow, field: str) -> str:
    return row.cells.get(field, "").strip()


def _row_fields(manifest: Path, row: ManifestRow) -> dict[str, Any]:
    where = f"manifest {manifest} {row.where}"
    for field in ("path", "condition", "recording_id", "channel"):
        if not _cell(row, field):
            raise SDTError(
                f"{where}: field 'path'/'condition'/'recording_id'/'channel' "
                f"must not be empty (field {field!r} is)"
            )
    try:
        text = _cell(row, "sampling_rate_hz")
        rate = float(text) if text else None
        if rate is not None and not (text.isascii() and np.isfinite(rate) and rate > 0):
            raise ValueError
    except ValueError:
        raise SDTError(
            f"{where}: field 'sampling_rate_hz' = {quote(_cell(row, 'sampling_rate_hz'))} "
            f"is not a positive number"
        ) from None
    units = _cell(row, "units")
    if units and units not in UNITS_TO_G:
        raise SDTError(
            f"{where}: field 'units' = {quote(units)}; use one of {', '.join(UNITS_TO_G)}"
        )
    file = Path(_cell(row, "path")).expanduser()
    return {
        "file": file if file.is_absolute() else manifest.parent / file,
        "rate": rate,
        "severity": severity_cell(where, _cell(row, "severity")),
        "speed_rpm": speed_rpm_cell(where, _cell(row, "speed_rpm")),
        "units": units,
        "variable": row.cells.get("variable", "") if _cell(row, "variable") else None,
        "machine": _cell(row, "machine") or "machine",
        "speed": _cell(row, "speed") or None,
        "condition": _cell(row, "condition"),
        "run": _cell(row, "recording_id"),
        "channel": _cell(row, "channel"),
        "line": row.number,
        "where": row.where,
        "cells": row.cells,
    }


def open_manifest(
    path: str | os.PathLike[str],
    *,
    readers: Sequence[Any],
    name: str = "manifest",
    validate: bool = False,
) -> Dataset:
    """Open a manifest file; see the module docstring for its columns.

    Parameters
    ----------
    path
        ``.csv`` or ``.parquet`` manifest.
    validate
        Read every signal now so that bad files land in ``skipped``.
    readers
        The signal readers (``ReaderSpec``) to read files with, handed down by the
        caller (``registry.signal_readers()``; ``load_dataset`` passes them).
    """
    manifest = Path(path).expanduser()
    columns, rows = read_manifest_rows(manifest)
    unknown = sorted(set(columns) - set(REQUIRED) - set(OPTIONAL))
    if unknown:
        raise SDTError(
            f"manifest {manifest}: unknown column(s) {', '.join(map(quote, unknown[:8]))}; "
            f"allowed: {', '.join(REQUIRED + OPTIONAL)}"
        )
    missing = [c for c in REQUIRED if c not in columns]
    if missing:
        raise SDTError(
            f"manifest {manifest}: missing required column(s) {', '.join(map(repr, missing))}"
        )
    all_fields = [_row_fields(manifest, row) for row in rows]
    refuse_identical(manifest, columns, rows)
    groups: dict[tuple[str, str, str], list[dict[str, Any]]] = {}
    signals: dict[tuple[str, str], str] = {}
    skipped: list[Skipped] = []
    notes: list[str] = []
    other_notes: list[str] = []
    for fields in all_fields:
        if not fields["file"].is_file():
            kind = not_regular(fields["file"])
            what = "is a folder" if fields["file"].is_dir() else "not found"
            what = f"is not a regular file ({kind})" if kind else what
            skipped.append(
                Skipped(str(fields["file"]), f"file {what} (manifest {manifest} {fields['where']})")
            )
            continue
        try:
            reader, info, options = probe_row(fields, readers)
        except DataFileError as exc:
            skipped.append(Skipped(str(fields["file"]), f"{exc} (manifest {fields['where']})"))
            continue
        except SignalTypeError as exc:
            raise SignalTypeError(f"{exc} (manifest {manifest} {fields['where']})") from None
        refuse_signal_twice(manifest, signals, fields, info)
        reconcile(fields, info, reader, manifest)
        fields["shape"], fields["load"] = info.shape, (reader.read, tuple(options.items()))
        if info.note:
            (notes if reader.name == "csv" else other_notes).append(info.note)
        key = (fields["machine"], fields["run"], fields["channel"])
        groups.setdefault(key, []).append(fields)
    refuse_shared_ids(manifest, groups)
    recordings, lines = [], {}
    for (machine, run, channel), rows in groups.items():
        first = rows[0]
        lengths = {r["shape"][1] for r in rows}
        keys = ("rate", "condition", "severity", "speed", "speed_rpm")
        meta = {k: {r[k] for r in rows} for k in keys}
        conflict = [k for k, v in meta.items() if len(v) > 1]
        if len(lengths) > 1 or conflict:
            what = ", ".join(conflict) or f"acquisition lengths {sorted(lengths)}"
            lines = ", ".join(r["where"] for r in rows)
            skipped.append(
                Skipped(
                    str(first["file"]),
                    f"machine {machine!r} recording {run!r} channel {channel!r}: "
                    f"rows disagree on {what} (manifest {manifest} {lines})",
                )
            )
            continue
        n_acq = sum(r["shape"][0] for r in rows)
        lines[f"{machine}/{run}/{channel}"] = ", ".join(r["where"] for r in rows)
        recordings.append(
            Recording(
                dataset=name,
                machine=machine,
                speed=first["speed"],
                condition=first["condition"],
                severity=first["severity"],
                run=run,
                channel=channel,
                recording_id=f"{machine}/{run}/{channel}",
                sampling_rate_hz=first["rate"],
                units=first["units"],
                n_acquisitions=n_acq,
                samples_per_acquisition=lengths.pop(),
                measurement=measurement_groups(n_acq),
                source=str(first["file"]),
                reader=partial(
                    _load_rows,
                    tuple((r["file"], r["variable"], r["units"], *r["load"]) for r in rows),
                ),
                speed_rpm=first["speed_rpm"],
            )
        )
    if len(notes) > 1:
        notes = [f"{len(notes)} CSV files had a time column, dropped; first: {notes[0]}"]
    notes += list(dict.fromkeys(other_notes))
    machines = _machines_beside(manifest, {r.machine for r in recordings}, notes)
    recordings = [
        replace(r, **speed_fields(r.speed_rpm, lines[r.recording_id], machines.get(r.machine)))
        for r in recordings
    ]
    dataset = Dataset(name, recordings, skipped, notes, machines)
    if validate:
        dataset.validate()
    return dataset


def _machines_beside(manifest: Path, names: set[str], notes: list[str]) -> dict[str, Any]:
    """The machines of ``machines.toml`` beside ``manifest`` (none without one); a machine
    the file describes that no row names is a note, not an error (a misspelt name)."""
    path = manifest.parent / MACHINE_FILE
    if not path.exists():
        return {}
    machines = load_machine_file(path)
    unused = sorted(set(machines) - names)
    if unused:
        notes.append(
            f"{path} describes {', '.join(map(quote, unused))}, which no manifest row names "
            f"(machines: {', '.join(map(quote, sorted(names)))})"
        )
    return machines


def _load_rows(rows: tuple[tuple[Path, str | None, str, Any, tuple], ...]) -> np.ndarray:
    parts = [
        read(file, variable, **dict(options)) * UNITS_TO_G[units]
        for file, variable, units, read, options in rows
    ]
    return np.concatenate(parts, axis=0)
