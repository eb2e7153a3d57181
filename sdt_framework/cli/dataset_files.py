"""``sdt dataset manifest`` and ``sdt dataset inspect FILE``: recordings as they come off a DAQ.

Both go through the registered signal readers (``sdt plugins list`` shows
them): a format a plugin adds is inspected and put in a manifest like a
built-in one. ``inspect`` lists a signal that cannot be read (a rate outside
25 Hz to 10 MHz, a unit that changes between segments) with a ``warning:``
naming why, and refuses a file none of whose signals can be read. Names from
a file are cut in the middle past 200 characters on the terminal (``--json``
keeps them whole). ``manifest`` warns where the ``{channel}`` of the pattern
merges signals of different names into one channel's acquisitions.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from ..io import atomic_write_text
from ..labels import middle_cut
from .common import (
    LABEL_LIMIT,
    console,
    err_console,
    print_json,
    registry,
    shorten_labels,
    table,
    warn,
)

__all__ = ["cell", "inspect_file", "is_manifest_csv", "manifest"]

SHOWN_UNMATCHED = 20
#: bytes of a .csv read to tell a manifest (a header naming its columns) from a signal
_HEAD_BYTES = 65_536


def cell(value: object) -> str:
    """``value`` for a table cell: a name over :data:`LABEL_LIMIT` characters cut in the middle,
    saying how long it was (a file's names can be of any length)."""
    text = str(value)
    return text if len(text) <= LABEL_LIMIT else middle_cut(text, 60, count=True)


def is_manifest_csv(path: Path) -> bool:
    """Whether the .csv at ``path`` is a manifest: its first line names one of the manifest's
    required columns (``path``, ``condition``...) or is empty; else it is a signal file."""
    from ..data import REQUIRED

    try:
        with open(path, "rb") as handle:
            head = handle.read(_HEAD_BYTES)
    except OSError:
        return True  # the manifest reader says what is wrong
    first = head.lstrip(b"\xef\xbb\xbf").split(b"\n", 1)[0].decode("utf-8", "replace")
    if not first.strip():
        return True  # empty: the manifest reader says so
    return any(c.strip().strip('"').strip() in REQUIRED for c in first.split(","))


def inspect_file(ctx: typer.Context, path: str, as_json: bool) -> None:
    """Every signal of one file: variable, rate and where it comes from, units, duration."""
    from ..signals import scan_file
    from .guards import os_errors

    with os_errors(path):
        reader, infos = scan_file(Path(path), registry(ctx).signal_readers())
    for note in dict.fromkeys(i.note for i in infos if i.note):
        err_console.print(f"note: {shorten_labels(note)}", markup=False, highlight=False,
                          soft_wrap=True)  # fmt: skip
    for fault in dict.fromkeys(i.fault for i in infos if i.fault):
        warn(f"listed, not read: {fault}")
    if as_json:
        print_json({"path": path, "format": reader.label, "reader": reader.name,
                    "signals": [i.as_dict() for i in infos]})  # fmt: skip
        return
    rows = [
        [
            "-" if i.variable is None else cell(i.variable),
            cell(i.label or "-"),
            i.n_acquisitions,
            i.n_samples,
            "-" if i.rate_hz is None else f"{i.rate_hz:.6g} ({i.rate_from})",
            cell(i.units or "-"),
            "-" if i.duration_s is None else f"{i.duration_s:.4g}",
        ]
        for i in infos
    ]
    table(
        f"{cell(path)}: {reader.label}, {len(infos)} signal{'' if len(infos) == 1 else 's'}",
        ["variable", "label", "acquisitions", "samples", "rate Hz", "units", "duration s"],
        rows,
    )


def manifest(
    ctx: typer.Context,
    folder: Annotated[Path, typer.Argument(help="Root folder of the recordings.")],
    pattern: Annotated[
        str,
        typer.Option(
            "--pattern",
            help="Path template below FOLDER with {machine} {speed} {condition} {severity} "
            "{run} {channel} ({severity?}: may be missing), e.g. "
            "'{machine}/{condition} {severity?}/{run}/{channel}.tdms'.",
        ),
    ],
    out: Annotated[Path, typer.Option("--out", help="Manifest to write (.csv).")],
    rate_hz: float | None = typer.Option(
        None, "--rate-hz", help="Rate of files that hold none (CSV, NPY, MAT), Hz."
    ),
    full_scale_g: float | None = typer.Option(
        None, "--full-scale-g", help="Acceleration at full scale of integer WAV files, g."
    ),
    overwrite: bool = typer.Option(False, "--overwrite", help="Replace an existing --out."),
) -> None:
    """Build a manifest from a folder tree: labels from the paths, rate and units from the files.

    Each file matching --pattern gives one row per signal it holds. With {channel}
    in the pattern a file's signals are that channel's acquisitions; without it,
    each signal is a channel named by the file. A field written {severity?} (also
    {machine?}, {speed?}) may be missing, so healthy folders without a severity
    ('healthy' beside 'bearing 2', or 'healthy/run1' beside 'bearing/2/run1') read
    with one pattern; a severity of '-' is healthy too. A signal whose file gives a
    unit that is not an acceleration (degC, V, Pa) is left out, counted in a note;
    so is one that cannot be read as it stands (a PSD beside a UFF file's time
    histories, a 1 Hz channel), with the reason; one whose file leaves its units
    empty (a TDMS channel without unit_string) is read in g, and a note says so.
    Linked folders are followed (loops are not); every file or folder not used (no
    match, no reader, a broken link, a FIFO) is listed with the reason.

    Example:

      python examples/daq_campaign.py campaign   # a campaign's TDMS files, for the lines below

      sdt dataset manifest campaign --out campaign.csv \\
        --pattern '{machine}/{condition} {severity?}/{run}.tdms'

      sdt benchmark --quick --data campaign.csv
    """
    from ..data import build_manifest, manifest_csv
    from .guards import check_output_file, os_errors

    check_output_file(out, "--out", (".csv",), overwrite=overwrite)
    with os_errors(str(folder)):
        built = build_manifest(
            folder,
            pattern,
            out.parent,
            rate_hz=rate_hz,
            full_scale_g=full_scale_g,
            readers=registry(ctx).signal_readers(),
        )
    atomic_write_text(out, manifest_csv(built))
    for note in built.notes:
        err_console.print(f"note: {note}", markup=False, highlight=False, soft_wrap=True)
    for path, why in built.unmatched[:SHOWN_UNMATCHED]:
        err_console.print(f"not used: {path}: {why}", markup=False, highlight=False,
                          soft_wrap=True)  # fmt: skip
    if len(built.unmatched) > SHOWN_UNMATCHED:
        err_console.print(f"not used: {len(built.unmatched) - SHOWN_UNMATCHED} more",
                          markup=False, highlight=False)  # fmt: skip
    _warn_merged(built.rows)
    recordings = {(r["machine"], r["recording_id"], r["channel"]) for r in built.rows}
    console.print(
        f"wrote {out}: {len(built.rows)} rows from {built.files} files ({len(recordings)} "
        f"recordings); {len(built.unmatched)} not used",
        highlight=False,
        soft_wrap=True,
    )


def _warn_merged(rows: list[dict[str, str]]) -> None:
    """Warn, per recording, where signals of different names became one channel's
    acquisitions (several NI channels of a file under one ``{channel}``)."""
    merged: dict[tuple[str, str, str], list[dict[str, str]]] = {}
    for row in rows:
        merged.setdefault((row["machine"], row["recording_id"], row["channel"]), []).append(row)
    found = [group for group in merged.values() if len({r["variable"] for r in group}) > 1]
    for group in found[:SHOWN_UNMATCHED]:
        variables = ", ".join(repr(r["variable"]) for r in group[:4])
        more = f" and {len(group) - 4} more" if len(group) > 4 else ""
        warn(
            f"{group[0]['path']}: signals {variables}{more} of different names are read as "
            f"{len(group)} acquisitions of one channel {group[0]['channel']!r} (the pattern's "
            f"{{channel}}); if they are different channels or axes, leave {{channel}} out of "
            f"--pattern so that each becomes a channel of its own"
        )
    if len(found) > SHOWN_UNMATCHED:
        warn(f"{len(found) - SHOWN_UNMATCHED} more recordings merge signals of different names")
