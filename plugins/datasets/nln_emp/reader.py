"""The NLN-EMP reader: discover the published folder layout, read CSVs lazily.

Layout (SPEC section 4)::

    <root>/Vibration/Motor-<k>/<speed>/<condition dir>/
        Vibration_Motor-<k>_<speed>_time-<condition dir>-ch<c>.csv

A condition directory is ``"<condition> <level>"``: for faults the level is the
severity, for ``healthy`` it numbers separate healthy runs. Directory names
outside the known classes (``coupling 2D``, ``healthy noise``) are reported in
``skipped`` unless named in ``conditions``. By default only the paper's subsets
are selected (Motor-4 at 70 %, Motor-2 at 100 %); ``speeds="all"`` reads every
speed folder (Motor-2 at 50, 75 and 100 %). Every recording carries the speed
of its folder (:mod:`.speeds`: ``speed_percent``, ``speed_rpm`` from the rig's
operating point, ``speed_source`` saying which). A machine read at several
speed folders has a run per folder: its ``run`` is ``"<speed>/<condition
dir>"`` (``"50/healthy 1"``), since ``healthy 1`` at 50 % and at 75 % are two
runs a split may put on two sides; read at one speed, it is the directory.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterable, Mapping
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from sdt_framework.data import ArrayCache, DataFileError, Dataset, Recording, Skipped
from sdt_framework.data.recording import measurement_groups
from sdt_framework.errors import SDTError
from sdt_framework.machine_files import spec_at_speeds
from sdt_framework.specs import MachineSpec

from ..pump_rig import rig_machines
from .csv_file import parse_nln_csv, read_header
from .speeds import FolderSpeed, asked_speeds, folder_speed, speed_filter

__all__ = ["PAPER_SUBSETS", "NlnEmpDataset", "open_nln_emp", "parse_condition"]

#: machine -> (speed, condition classes) used in the paper
PAPER_SUBSETS: dict[str, tuple[str, tuple[str, ...]]] = {
    "Motor-4": (
        "70",
        (
            "healthy",
            "unbalance motor",
            "unbalance pump",
            "align angular",
            "align parallel",
            "align combination",
            "coupling",
            "cavitation suction",
            "cavitation discharge",
        ),
    ),
    "Motor-2": ("100", ("healthy", "impeller", "bearing bpfo", "bearing bpfi", "bearing pump")),
}

_CONDITION = re.compile(r"^(?P<name>[a-z][a-z ]*?) (?P<level>\d+)$")
_FILE = re.compile(
    r"^Vibration_(?P<machine>Motor-\d+)_(?P<speed>[^_]+)_time-(?P<cond>.+)-(?P<ch>ch\d+)\.csv$"
)


def parse_condition(directory: str) -> tuple[str, int | None]:
    """``"align angular 3"`` -> ("align angular", 3); ``"healthy 2"`` -> ("healthy", None).

    Raises
    ------
    ValueError
        If the name is not ``"<words> <number>"``.
    """
    match = _CONDITION.match(directory.strip().lower())
    if not match:
        raise ValueError(f"{directory!r} is not '<condition> <level>'")
    name = match["name"]
    return name, None if name == "healthy" else int(match["level"])


def _as_set(value: str | Iterable[str] | None) -> set[str] | None:
    if value is None:
        return None
    return {value} if isinstance(value, str) else {str(v) for v in value}


class NlnEmpDataset(Dataset):
    """Recordings found under an NLN-EMP root (see module docstring for options)."""


def open_nln_emp(
    path: str | os.PathLike[str],
    *,
    motors: str | Iterable[str] | None = None,
    speeds: str | float | Iterable[str | float] | Mapping[str, Any] | None = None,
    conditions: str | Iterable[str] | None = None,
    channels: str | Iterable[str] | None = None,
    max_acquisitions: int | None = None,
    cache: bool = True,
    cache_dir: str | os.PathLike[str] | None = None,
    validate: bool = False,
    name: str = "nln-emp",
) -> NlnEmpDataset:
    """Open an NLN-EMP root (the folder holding ``Vibration/``, or ``Vibration/`` itself).

    Parameters
    ----------
    motors
        Machines to read (``"Motor-4"``); default the paper's two.
    speeds
        Speed folders: ``"all"``, one (``"70"`` or ``70``) or a list (``[50, 75, 100]``),
        or a mapping machine -> those; default the paper's (a machine the mapping
        does not name: the paper's). A machine with none of the speeds named is a note.
    conditions
        Condition classes (``"align angular"``) or exact directory names
        (``"coupling 2D"``); default the paper's classes of each machine.
    channels
        ``"ch1"``..``"ch5"``; default all found.
    max_acquisitions
        Keep only the first K columns of each file (None: all).
    cache, cache_dir
        Store parsed arrays (default ``$SDT_CACHE_DIR`` or ``~/.cache/sdt-framework``).
    validate
        Parse every file now (filling the cache) so malformed ones land in ``skipped``.
    """
    root = Path(path).expanduser()
    vib = root if root.name == "Vibration" else root / "Vibration"
    if not vib.is_dir():
        raise SDTError(
            f"{root}: no 'Vibration' folder; expected the NLN-EMP layout "
            f"Vibration/Motor-<k>/<speed>/<condition>/...csv"
        )
    if max_acquisitions is not None and max_acquisitions < 1:
        raise SDTError(f"max_acquisitions must be >= 1, got {max_acquisitions}")
    asked_speeds(speeds, "")  # a bad speed is refused before the walk
    store = ArrayCache(cache_dir, enabled=cache)
    wanted_motors = _as_set(motors) or set(PAPER_SUBSETS)
    wanted_channels = _as_set(channels)
    wanted_conditions = _as_set(conditions)
    recordings: list[Recording] = []
    skipped: list[Skipped] = []
    missing: list[str] = []
    rig = rig_machines()
    for machine_dir in sorted(p for p in vib.iterdir() if p.is_dir()):
        machine = machine_dir.name
        if machine not in wanted_motors:
            continue
        paper = PAPER_SUBSETS.get(machine, ("", ()))
        wanted = speed_filter(speeds, machine, paper[0] or None)
        classes = wanted_conditions or set(paper[1])
        folders = sorted(p for p in machine_dir.iterdir() if p.is_dir())
        chosen = [p for p in folders if wanted is None or wanted(p.name)]
        if asked_speeds(speeds, machine) is not None and not chosen:
            missing.append(f"{machine} ({', '.join(p.name for p in folders) or 'none'})")
        for speed_dir in chosen:
            speed = folder_speed(machine, speed_dir.name, rig.get(machine))
            prefix = f"{speed_dir.name}/" if len(chosen) > 1 else ""  # a run per speed
            for cond_dir in sorted(p for p in speed_dir.iterdir() if p.is_dir()):
                _scan_condition(
                    cond_dir,
                    machine,
                    (speed_dir.name, speed, prefix),
                    classes,
                    wanted_channels,
                    max_acquisitions,
                    store,
                    name,
                    recordings,
                    skipped,
                )
    machines, notes = _machines(recordings)
    if missing:
        notes.append(
            f"no speed folder selected by speeds={speeds!r} for {'; '.join(missing)} "
            f"(folders it has in brackets)"
        )
    dataset = NlnEmpDataset(name, recordings, skipped, notes, machines)
    if validate:
        dataset.validate()
    return dataset


def _machines(recordings: list[Recording]) -> tuple[dict[str, MachineSpec], list[str]]:
    """The rig's machines read at the speed their spec is for, and a note for each other
    (:func:`~sdt_framework.machine_files.spec_at_speeds`, as the synthetic pump decides)."""
    rig = rig_machines()
    machines, notes = {}, []
    for name in sorted({r.machine for r in recordings} & set(rig)):
        speeds = [r.speed or "" for r in recordings if r.machine == name]
        spec, note = spec_at_speeds(name, rig[name], speeds)
        if spec is not None:
            machines[name] = spec
        if note:
            notes.append(note)
    return machines, notes


def _scan_condition(
    cond_dir: Path,
    machine: str,
    folder: tuple[str, FolderSpeed, str],
    classes: set[str],
    channels: set[str] | None,
    max_acquisitions: int | None,
    store: ArrayCache,
    name: str,
    recordings: list[Recording],
    skipped: list[Skipped],
) -> None:
    run = cond_dir.name
    speed, (percent, rpm, speed_source), prefix = folder
    try:
        condition, severity = parse_condition(run)
    except ValueError as exc:
        if run not in classes:
            skipped.append(Skipped(str(cond_dir), f"unknown condition directory: {exc}"))
            return
        condition, severity = run, None
    if condition not in classes and run not in classes:
        if condition in {c for m in PAPER_SUBSETS.values() for c in m[1]}:
            return  # a known class not selected for this machine: not an error, not listed
        skipped.append(
            Skipped(
                str(cond_dir),
                f"condition {condition!r} not selected "
                f"(known classes: {', '.join(sorted(classes))})",
            )
        )
        return
    for file in sorted(cond_dir.iterdir()):
        match = _FILE.match(file.name)
        if not match or match["cond"] != run or match["machine"] != machine:
            skipped.append(
                Skipped(
                    str(file),
                    f"file name does not follow Vibration_{machine}_{speed}_time-{run}-ch<c>.csv",
                )
            )
            continue
        if channels is not None and match["ch"] not in channels:
            continue
        try:
            header = read_header(file)
        except (DataFileError, OSError) as exc:
            skipped.append(Skipped(str(file), str(exc)))
            continue
        n_acq = len(header.columns) - 1
        if max_acquisitions is not None:
            n_acq = min(n_acq, max_acquisitions)
        recordings.append(
            Recording(
                dataset=name,
                machine=machine,
                speed=speed,
                condition=condition,
                severity=severity,
                run=prefix + run,
                channel=match["ch"],
                recording_id=f"{machine}/{speed}/{run}/{match['ch']}",
                sampling_rate_hz=header.sampling_rate_hz,
                units="g",
                n_acquisitions=n_acq,
                samples_per_acquisition=header.n_rows,
                measurement=measurement_groups(n_acq),
                source=str(file),
                reader=partial(_read, file, store, header.time_step_s, n_acq),
                speed_rpm=rpm,
                speed_percent=percent,
                speed_source=speed_source,
            )
        )


def _read(file: Path, store: ArrayCache, step: float, n_acq: int) -> np.ndarray:
    try:
        data = store.get_or_compute(file, lambda: parse_nln_csv(file, step), variant="nln-csv")
    except OSError as exc:
        raise DataFileError(f"{file}: cannot read ({exc.strerror or exc})") from None
    return data[:n_acq]
