"""Build a manifest from a folder tree: labels from the paths, rate and units from the files.

A template such as ``{machine}/{condition} {severity}/{run}/{channel}.tdms``
is matched against every file's path relative to the folder (``/``
separated). Fields: ``machine``, ``speed``, ``condition``, ``severity``,
``run`` and ``channel``; each matches one or more characters within one
folder or file name (``severity``: a whole number, or ``-`` for healthy), the
rest of the template literally. ``condition`` and ``run`` are required.

Each matched file is scanned by its registered reader
(:func:`~sdt_framework.data.signal_files.scan_file`) and gives one row per
signal it holds: its ``variable``, the file's rate and units (a format that
holds no rate takes ``rate_hz``). When the template names the channel, a
file's signals are that channel's acquisitions (rows sharing machine, run and
channel are one recording's acquisitions in a manifest); when it does not,
each signal is its own channel, named by the file. Files that do not match, or
that no reader reads, are returned with the reason, never dropped silently.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import SDTError
from .readers import SignalInfo, acceleration_units
from .signal_files import scan_file
from .tokens import quote

__all__ = ["FIELDS", "BuiltManifest", "build_manifest", "compile_template", "manifest_csv"]

FIELDS = ("machine", "speed", "condition", "severity", "run", "channel")
REQUIRED_FIELDS = ("condition", "run")
COLUMNS = ("path", "sampling_rate_hz", "condition", "severity", "recording_id", "channel",
           "machine", "units", "variable", "speed", "full_scale_g")  # fmt: skip
_FIELD = re.compile(r"\{([^{}]*)\}")


@dataclass
class BuiltManifest:
    """Manifest rows (column -> text), files read and matched, and those left out with why."""

    rows: list[dict[str, str]] = field(default_factory=list)
    files: int = 0
    matched: int = 0
    unmatched: list[tuple[str, str]] = field(default_factory=list)


def _segment_regex(segment: str, template: str) -> str:
    out, pos = [], 0
    for found in _FIELD.finditer(segment):
        name = found.group(1)
        if name not in FIELDS:
            raise SDTError(
                f"--pattern {quote(template, 80)}: unknown field {{{quote(name)}}}; "
                f"use {', '.join('{' + f + '}' for f in FIELDS)}"
            )
        value = r"\d+|-" if name == "severity" else "[^/]+?"
        out += [re.escape(segment[pos : found.start()]), f"(?P<{name}>{value})"]
        pos = found.end()
    return "".join([*out, re.escape(segment[pos:])])


def compile_template(template: str) -> list[tuple[str, re.Pattern[str]]]:
    """One compiled pattern per ``/``-separated part of ``template``; bad templates refused."""
    names = _FIELD.findall(template)
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
            return f"{quote(part, 60)} does not match {quote(segment, 60)}"
        fields.update(found.groupdict())
    severity = fields.get("severity", "")
    fields["severity"] = "" if severity == "-" else severity
    return fields


def _row(file: Path, out_dir: Path, fields: dict[str, str], info: SignalInfo,
         rate_hz: float | None, full_scale_g: str) -> dict[str, str]:  # fmt: skip
    """One manifest row: labels from the path, rate and units from the file."""
    try:
        path = file.resolve().relative_to(out_dir.resolve()).as_posix()
    except ValueError:
        path = str(file.resolve())
    rate = info.rate_hz if info.rate_hz is not None else rate_hz
    return {
        "path": path,
        "sampling_rate_hz": repr(float(rate)),  # type: ignore[arg-type]
        "condition": fields["condition"],
        "severity": fields["severity"],
        "recording_id": fields["run"],
        "channel": fields.get("channel") or str(info.variable or file.stem).replace("/", "-"),
        "machine": fields.get("machine", ""),
        "units": (acceleration_units(info.units) if info.units else None) or "",
        "variable": "" if info.variable is None else str(info.variable),
        "speed": fields.get("speed", ""),
        "full_scale_g": full_scale_g,
    }


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
    if not folder.is_dir():
        raise SDTError(f"{folder}: not a folder; give the root of the recordings")
    built = BuiltManifest()
    files = sorted(p for p in folder.rglob("*") if p.is_file())
    for file in files:
        relative = file.relative_to(folder)
        fields = _match(relative.parts, patterns)
        if isinstance(fields, str):
            built.unmatched.append((relative.as_posix(), fields))
            continue
        built.matched += 1
        options = {"full_scale_g": full_scale_g} if full_scale_g is not None else {}
        try:
            reader, infos = scan_file(file, readers)
            if "full_scale_g" in reader.options:
                infos = reader.scan(file, **options)
                for info in infos:  # a probe refuses what the row could not read
                    reader.probe(file, info.variable, **options)
        except SDTError as exc:
            built.unmatched.append((relative.as_posix(), str(exc)))
            continue
        if rate_hz is None and any(info.rate_hz is None for info in infos):
            why = f"a {reader.label} file holds no rate; give --rate-hz"
            built.unmatched.append((relative.as_posix(), why))
            continue
        built.files += 1
        scale = repr(full_scale_g) if options and "full_scale_g" in reader.options else ""
        built.rows += [_row(file, out_dir, fields, info, rate_hz, scale) for info in infos]
    if not built.rows:
        first = (
            f"; first: {built.unmatched[0][0]}: {built.unmatched[0][1]}" if built.unmatched else ""
        )
        what = (
            f"matches {built.matched} of the {len(files)} files under {folder} and none of them "
            f"could be read" if built.matched else
            f"matches none of the {len(files)} files under {folder}"
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
    writer.writerows([r[c] for c in used] for r in built.rows)
    return buffer.getvalue()
