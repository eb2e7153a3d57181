"""Build a manifest from a folder tree: labels from the paths, rate and units from the files.

The template (:mod:`.manifest_pattern`, e.g.
``{machine}/{condition} {severity?}/{run}/{channel}.tdms``) gives each
file's labels from its path. Each matched file is scanned by its registered
reader (:func:`~sdt_framework.signals.files.scan_file`) and gives one
row per signal it holds: its ``variable`` written as the file names it
(spaces included: the manifest reader matches it so), the file's rate and
units (a format that holds no rate takes ``rate_hz``). When the template
names the channel, a file's signals are that channel's acquisitions (rows
sharing machine, run and channel are one recording's acquisitions in a
manifest); when it does not, each signal is its own channel, named by the
file.

A DAQ file often logs more than vibration: a temperature in ``degC``, a
tachometer in ``V``, a pressure in ``hPa`` beside the ``g`` channels. A
signal whose file gives a unit that is not an acceleration is not put in the
manifest (the reader would refuse the whole manifest for it); the channels so
skipped are counted by unit in a note, and a file left with none is listed as
not used. A signal whose file states no unit is taken, in g, and a note names
it where its format has a units field it left empty (a TDMS channel without
``unit_string``). A signal its reader lists but cannot read as it stands (an
FRF or a spectrum beside a UFF file's time histories, a 1 Hz channel beside
the accelerometers) is left out and counted in a note with the first reason;
the file's other signals are written.

Every entry of the tree is accounted for (:mod:`.manifest_walk`: linked
folders followed, loops, broken links and FIFOs named): files that do not
match, that no reader reads, or that are not regular files are returned with
the reason, never dropped silently. Each run and channel is its own recording
(:mod:`.manifest_ids`). Cells are written spreadsheet-safe
(:mod:`sdt_framework.csv_cells`).
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..csv_cells import escape_cell
from ..errors import SDTError
from ..signals.files import scan_file
from ..signals.rules import SignalInfo, acceleration_units, fault_of
from ..signals.tokens import quote
from .manifest_ids import Matched, name_recordings
from .manifest_pattern import compile_template
from .manifest_walk import walk_tree

__all__ = ["BuiltManifest", "build_manifest", "manifest_csv"]

COLUMNS = ("path", "sampling_rate_hz", "condition", "severity", "recording_id", "channel",
           "machine", "units", "variable", "speed", "full_scale_g")  # fmt: skip


@dataclass
class BuiltManifest:
    """Manifest rows (column -> text), files read and matched, entries left out with why, and
    notes (run ids built from labels, channel names numbered)."""

    rows: list[dict[str, str]] = field(default_factory=list)
    files: int = 0
    matched: int = 0
    unmatched: list[tuple[str, str]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def _row(m: Matched, info: SignalInfo, channel: str, out_dir: Path,
         rate_hz: float | None) -> dict[str, str]:  # fmt: skip
    """One manifest row: labels from the path, rate and units from the file."""
    try:
        path = m.file.resolve().relative_to(out_dir.resolve()).as_posix()
    except ValueError:
        path = str(m.file.resolve())
    rate = info.rate_hz if info.rate_hz is not None else rate_hz
    return {
        "path": path,
        "sampling_rate_hz": repr(float(rate)),  # type: ignore[arg-type]
        "condition": m.fields["condition"],
        "severity": m.fields["severity"],
        "recording_id": m.run_id,
        "channel": channel,
        "machine": m.fields.get("machine", ""),
        "units": acceleration_units(info.units) or "",
        "variable": "" if info.variable is None else str(info.variable),
        "speed": m.fields.get("speed", ""),
        "full_scale_g": m.full_scale_g,
    }


def _positive(option: str, value: float | None) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise SDTError(f"{option} {value:g}: give a finite number above 0")


def _not_acceleration(info: SignalInfo) -> bool:
    """The file states a unit, and it is not an acceleration (degC, V, Pa...)."""
    return bool(info.units and info.units.strip()) and acceleration_units(info.units) is None


def _skipped_note(skipped: list[tuple[str, SignalInfo]]) -> list[str]:
    """One note counting the signals left out for their units, by unit."""
    if not skipped:
        return []
    units = Counter(str(info.units).strip() for _, info in skipped)
    counts = ", ".join(f"{quote(unit)}: {n}" for unit, n in units.most_common())
    where, info = skipped[0]
    files = len({w for w, _ in skipped})
    return [
        f"{_count(len(skipped), 'signal')} skipped: not an acceleration unit ({counts}), in "
        f"{_count(files, 'file')} (e.g. {quote(info.variable, 60)} in {where}); "
        f"`sdt dataset inspect FILE` lists each signal with its units"
    ]


def _unread_notes(unreadable: list[tuple[str, SignalInfo, str]],
                  unstated: list[tuple[str, SignalInfo]]) -> list[str]:  # fmt: skip
    """Notes on the signals left out as unreadable, and on those read in g for want of units."""
    notes = []
    if unreadable:
        where, info, why = unreadable[0]
        notes.append(
            f"{_count(len(unreadable), 'signal')} skipped: not readable as they stand, in "
            f"{_count(len({w for w, _, _ in unreadable}), 'file')} (e.g. "
            f"{quote(info.variable, 60)} in {where}: {why}); `sdt dataset inspect FILE` says why "
            f"for each"
        )
    if unstated:
        where, info = unstated[0]
        fields = ", ".join(sorted({i.units_field for _, i in unstated}))
        verb = "states" if len(unstated) == 1 else "state"
        notes.append(
            f"{_count(len(unstated), 'signal')} {verb} no units (their {fields} is empty), in "
            f"{_count(len({w for w, _ in unstated}), 'file')} (e.g. {quote(info.variable, 60)} "
            f"in {where}): written with units empty, which the manifest reads as g; give their "
            f"units in the manifest's units column if they are not in g"
        )
    return notes


def _count(n: int, noun: str) -> str:
    return f"{n} {noun}{'' if n == 1 else 's'}"


def build_manifest(
    folder: Path,
    template: str,
    out_dir: Path,
    *,
    readers: Sequence[Any],
    rate_hz: float | None = None,
    full_scale_g: float | None = None,
) -> BuiltManifest:
    """Rows for every file under ``folder`` that matches ``template``, read by ``readers``
    (``registry.signal_readers()``, handed down); paths relative to ``out_dir`` (the
    manifest's folder) where they can be."""
    compiled = compile_template(template)
    _positive("--rate-hz", rate_hz)
    _positive("--full-scale-g", full_scale_g)
    if not folder.is_dir():
        raise SDTError(f"{folder}: not a folder; give the root of the recordings")
    built = BuiltManifest()
    tree = walk_tree(folder)
    matched: list[Matched] = []
    skipped: list[tuple[str, SignalInfo]] = []
    unreadable: list[tuple[str, SignalInfo, str]] = []
    options = {"full_scale_g": full_scale_g} if full_scale_g is not None else {}
    for relative, file in tree.files:
        fields = compiled.match(relative.parts)
        if isinstance(fields, str):
            built.unmatched.append((relative.as_posix(), fields))
            continue
        built.matched += 1
        try:
            reader, infos = scan_file(file, readers)
            if "full_scale_g" in reader.options:
                infos = reader.scan(file, **options)
            other = [info for info in infos if _not_acceleration(info)]
            faulty = [i for i in infos if not _not_acceleration(i) and fault_of(file, i)]
            infos = [i for i in infos if not _not_acceleration(i) and not fault_of(file, i)]
            skipped += [(relative.as_posix(), info) for info in other]
            unreadable += [(relative.as_posix(), i, str(fault_of(file, i)).removeprefix(
                f"{file}: ")) for i in faulty]  # fmt: skip
            if "full_scale_g" in reader.options:
                for info in infos:  # a probe refuses what the row could not read
                    reader.probe(file, info.variable, **options)
        except SDTError as exc:  # the reason without the file's path, which the line names
            built.unmatched.append((relative.as_posix(), str(exc).removeprefix(f"{file}: ")))
            continue
        if not infos:
            units = ", ".join(dict.fromkeys(quote(str(i.units).strip()) for i in other))
            why = f"no acceleration signal: its {_count(len(other), 'signal')} are in {units}"
            if faulty:
                why += f"; the {_count(len(faulty), 'other')} cannot be read as they stand"
            built.unmatched.append((relative.as_posix(), why))
            continue
        if rate_hz is None and any(info.rate_hz is None for info in infos):
            why = f"a {reader.label} file holds no rate; give --rate-hz"
            built.unmatched.append((relative.as_posix(), why))
            continue
        scale = repr(full_scale_g) if options and "full_scale_g" in reader.options else ""
        matched.append(Matched(relative, file, fields, list(infos), scale))
    built.unmatched = sorted(built.unmatched + tree.left_out)
    built.notes = name_recordings(matched, template, "channel" in compiled.names)
    built.notes += _skipped_note(skipped)
    unstated = [(m.where.as_posix(), i) for m in matched for i in m.infos
                if i.units_stated is False]  # fmt: skip
    built.notes += _unread_notes(unreadable, unstated)
    built.files = len(matched)
    built.rows = [
        _row(m, info, channel, out_dir, rate_hz)
        for m in matched
        for info, channel in zip(m.infos, m.channels, strict=True)
    ]
    if not built.rows:
        first = (
            f"; first: {built.unmatched[0][0]}: {built.unmatched[0][1]}" if built.unmatched else ""
        )
        what = (
            f"matches {built.matched} of the {len(tree.files)} files under {folder} and none of "
            f"them could be read" if built.matched else
            f"matches none of the {len(tree.files)} files under {folder}"
        )  # fmt: skip
        raise SDTError(f"--pattern {quote(template, 80)} {what}{first}")
    return built


def manifest_csv(built: BuiltManifest) -> str:
    """The rows as manifest CSV text (only the columns some row fills, required ones always)."""
    import csv
    import io

    used = [c for c in COLUMNS if c in COLUMNS[:6] or any(r[c] for r in built.rows)]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(used)
    writer.writerows([escape_cell(r[c]) for c in used] for r in built.rows)
    return buffer.getvalue()
