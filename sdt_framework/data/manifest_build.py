"""Build a manifest from a folder tree: labels from the paths, rate and units from the files.

A template such as ``{machine}/{condition} {severity}/{run}/{channel}.tdms``
is matched against every file's path relative to the folder (``/``
separated). Fields: ``machine``, ``speed``, ``condition``, ``severity``,
``run`` and ``channel``; each matches one or more characters within one
folder or file name (``severity``: a whole number in ASCII digits ``0-9``, or
``-`` for healthy; a Unicode digit class would take an Arabic-Indic ``٣`` for
3), the rest of the template literally. ``condition`` and ``run`` are
required; an unknown field (``{cond}``) or a lone brace is refused naming it
and the known ones.

Each matched file is scanned by its registered reader
(:func:`~sdt_framework.data.signal_files.scan_file`) and gives one row per
signal it holds: its ``variable``, the file's rate and units (a format that
holds no rate takes ``rate_hz``). When the template names the channel, a
file's signals are that channel's acquisitions (rows sharing machine, run and
channel are one recording's acquisitions in a manifest); when it does not,
each signal is its own channel, named by the file. Every entry of the tree
is accounted for (:mod:`.manifest_walk`: linked folders followed, loops,
broken links and FIFOs named): files that do not match, that no reader reads,
or that are not regular files are returned with the reason, never dropped
silently. Each run and channel is its own recording (:mod:`.manifest_ids`).
Cells are written spreadsheet-safe (:mod:`sdt_framework.csv_cells`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..csv_cells import escape_cell
from ..errors import SDTError
from .manifest_ids import Matched, name_recordings
from .manifest_walk import walk_tree
from .readers import SignalInfo, acceleration_units
from .signal_files import scan_file
from .tokens import quote

__all__ = ["FIELDS", "BuiltManifest", "build_manifest", "compile_template", "manifest_csv"]

FIELDS = ("machine", "speed", "condition", "severity", "run", "channel")
REQUIRED_FIELDS = ("condition", "run")
COLUMNS = ("path", "sampling_rate_hz", "condition", "severity", "recording_id", "channel",
           "machine", "units", "variable", "speed", "full_scale_g")  # fmt: skip
_FIELD = re.compile(r"\{([^{}]*)\}")
_KNOWN = ", ".join("{" + f + "}" for f in FIELDS)


@dataclass
class BuiltManifest:
    """Manifest rows (column -> text), files read and matched, entries left out with why, and
    notes (run ids built from labels, channel names numbered)."""

    rows: list[dict[str, str]] = field(default_factory=list)
    files: int = 0
    matched: int = 0
    unmatched: list[tuple[str, str]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def _segment_regex(segment: str, template: str) -> str:
    out, pos = [], 0
    for found in _FIELD.finditer(segment):
        name = found.group(1)
        value = "[0-9]+|-" if name == "severity" else "[^/]+?"  # not \d: ٣ is no level
        out += [re.escape(segment[pos : found.start()]), f"(?P<{name}>{value})"]
        pos = found.end()
    return "".join([*out, re.escape(segment[pos:])])


def compile_template(template: str) -> list[tuple[str, re.Pattern[str]]]:
    """One compiled pattern per ``/``-separated part of ``template``; bad templates refused."""
    names = _FIELD.findall(template)
    unknown = [name for name in dict.fromkeys(names) if name not in FIELDS]
    if unknown:
        raise SDTError(
            f"--pattern {quote(template, 80)}: unknown field(s) "
            f"{', '.join('{' + quote(n, 40)[1:-1] + '}' for n in unknown)}; the fields are {_KNOWN}"
        )
    stray = _FIELD.sub("", template)
    if "{" in stray or "}" in stray:
        raise SDTError(
            f"--pattern {quote(template, 80)}: a {'{' if '{' in stray else '}'!r} without its "
            f"pair; write each field as {{name}}, one of {_KNOWN}"
        )
    missing = [f for f in REQUIRED_FIELDS if f not in names]
    if missing:
        raise SDTError(
            f"--pattern {quote(template, 80)}: names no {{{missing[0]}}}; a manifest needs the "
            f"condition and the run of every file"
        )
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise SDTError(f"--pattern {quote(template, 80)}: field {{{repeated[0]}}} appears twice")
    parts = template.strip("/").split("/")
    return [(part, re.compile(_segment_regex(part, template))) for part in parts]


def _match(
    parts: Sequence[str], patterns: list[tuple[str, re.Pattern[str]]]
) -> dict[str, str] | str:
    """The fields of a path, or why it does not match."""
    if len(parts) != len(patterns):
        return f"{len(parts)} path levels, the pattern has {len(patterns)}"
    fields: dict[str, str] = {}
    for part, (segment, pattern) in zip(parts, patterns, strict=True):
        found = pattern.fullmatch(part)
        if found is None:
            digits = "{severity}" in segment and any(c.isdigit() and not c.isascii() for c in part)
            hint = "; {severity} is ASCII digits 0-9 or '-'" if digits else ""
            return f"{quote(part, 60)} does not match {quote(segment, 60)}{hint}"
        fields.update({name: value.strip() for name, value in found.groupdict().items()})
    empty = [name for name, value in fields.items() if not value]
    if empty:  # the manifest reader strips labels: a blank one would be no label
        return f"{{{empty[0]}}} is only spaces"
    severity = fields.get("severity", "")
    fields["severity"] = "" if severity == "-" else severity
    return fields


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
        "units": (acceleration_units(info.units) if info.units else None) or "",
        "variable": "" if info.variable is None else str(info.variable),
        "speed": m.fields.get("speed", ""),
        "full_scale_g": m.full_scale_g,
    }


def _positive(option: str, value: float | None) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise SDTError(f"{option} {value:g}: give a finite number above 0")


def build_manifest(
    folder: Path,
    template: str,
    out_dir: Path,
    *,
    rate_hz: float | None = None,
    full_scale_g: float | None = None,
    readers: Sequence[Any] | None = None,
) -> BuiltManifest:
    """Rows for every file under ``folder`` that matches ``template``; paths relative to
    ``out_dir`` (the manifest's folder) where they can be."""
    patterns = compile_template(template)
    _positive("--rate-hz", rate_hz)
    _positive("--full-scale-g", full_scale_g)
    if not folder.is_dir():
        raise SDTError(f"{folder}: not a folder; give the root of the recordings")
    built = BuiltManifest()
    tree = walk_tree(folder)
    matched: list[Matched] = []
    options = {"full_scale_g": full_scale_g} if full_scale_g is not None else {}
    for relative, file in tree.files:
        fields = _match(relative.parts, patterns)
        if isinstance(fields, str):
            built.unmatched.append((relative.as_posix(), fields))
            continue
        built.matched += 1
        try:
            reader, infos = scan_file(file, readers)
            if "full_scale_g" in reader.options:
                infos = reader.scan(file, **options)
                for info in infos:  # a probe refuses what the row could not read
                    reader.probe(file, info.variable, **options)
        except SDTError as exc:  # the reason without the file's path, which the line names
            built.unmatched.append((relative.as_posix(), str(exc).removeprefix(f"{file}: ")))
            continue
        if rate_hz is None and any(info.rate_hz is None for info in infos):
            why = f"a {reader.label} file holds no rate; give --rate-hz"
            built.unmatched.append((relative.as_posix(), why))
            continue
        scale = repr(full_scale_g) if options and "full_scale_g" in reader.options else ""
        matched.append(Matched(relative, file, fields, list(infos), scale))
    built.unmatched = sorted(built.unmatched + tree.left_out)
    built.notes = name_recordings(matched, template, "channel" in _FIELD.findall(template))
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
