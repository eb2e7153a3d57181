"""A manifest row against its file: the reader that reads it, and the rate and units the file holds.

A manifest row names a file; the registered reader of that file
(:func:`~sdt_framework.signals.files.reader_for`) says what it holds
(:class:`~sdt_framework.signals.rules.SignalInfo`). Where the file states a
rate (TDMS ``wf_increment``, UFF58 ``abscissa_inc``, WAV header, LVM
``Delta_X``, IDE timestamps) or units, the row's own values must agree with
it, within the reader's tolerance: a manifest that disagrees with its file is
refused naming both values, since either one is wrong and a benchmark run on
the wrong rate is wrong throughout. A row may leave ``sampling_rate_hz`` or
``units`` empty where the file states them.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

from ..errors import SDTError
from ..signals.errors import DataFileError
from ..signals.files import reader_for
from ..signals.rules import SignalInfo, acceleration_units
from ..signals.tokens import quote

__all__ = ["probe_row", "reconcile"]


def probe_row(
    fields: dict[str, Any], readers: Sequence[Any]
) -> tuple[Any, SignalInfo, dict[str, str]]:
    """(reader, signal, reader options) of a row; a bad file raises ``DataFileError``.

    The row's ``variable`` names the signal whose name is the same, spaces
    included (``sdt dataset manifest`` writes names so); where no signal has
    that name, the one signal whose name is the same without leading and
    trailing spaces (a name typed by hand, or trimmed by a spreadsheet), and
    ``fields["variable"]`` becomes its name in the file."""
    reader = reader_for(fields["file"], readers)
    options = {k: fields["cells"][k] for k in reader.options if fields["cells"].get(k)}
    variable = fields["variable"]
    try:
        return reader, reader.probe(fields["file"], variable, **options), options
    except DataFileError as exc:
        if variable is None:
            raise
        unmatched = exc
    alike = [
        info.variable
        for info in reader.scan(fields["file"], **options)
        if info.variable is not None and str(info.variable).strip() == variable.strip()
    ]
    if len(alike) != 1 or alike[0] == variable:
        raise unmatched
    fields["variable"] = alike[0]
    return reader, reader.probe(fields["file"], alike[0], **options), options


def reconcile(fields: dict[str, Any], info: SignalInfo, reader: Any, manifest: Path) -> None:
    """Fill the row's empty rate and units from the file; refuse values that contradict it."""
    where = f"(manifest {manifest} {fields['where']})"
    what = f"{fields['file']}" + (f" signal {quote(info.variable)}" if info.variable else "")
    if info.rate_hz is not None:
        if fields["rate"] is None:
            fields["rate"] = info.rate_hz
        elif abs(fields["rate"] / info.rate_hz - 1) > info.rate_tolerance:
            raise SDTError(
                f"{what}: runs at {info.rate_hz:.6g} Hz by its {info.rate_from}, the manifest "
                f"says {fields['rate']:g} Hz {where}; correct sampling_rate_hz, or leave it "
                f"empty to take the file's rate (`sdt dataset inspect FILE` prints it)"
            )
    elif fields["rate"] is None:
        raise SDTError(
            f"{what}: field 'sampling_rate_hz' is empty and a {reader.label} file holds no "
            f"rate {where}; give the rate in Hz"
        )
    if info.units is None:
        fields["units"] = fields["units"] or "g"
        return
    units = acceleration_units(info.units)
    if units is None:
        raise SDTError(
            f"{what}: the file gives its units as {quote(info.units)}, not an acceleration "
            f"(g, mg, m/s^2) {where}; scale the channel to acceleration where it was recorded"
        )
    if fields["units"] and fields["units"] != units:
        raise SDTError(
            f"{what}: the file gives its units as {quote(info.units)}, the manifest says "
            f"units = {fields['units']} {where}; correct the manifest or leave the field empty"
        )
    fields["units"] = units
