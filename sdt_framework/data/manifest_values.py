"""The manifest's number cells: a fault level and a shaft speed, each checked where it is read.

``severity`` is a whole fault level or empty (healthy); ``speed_rpm`` is the
shaft speed the row was recorded at, in rpm, or empty where it is not known.
A cell that is neither (``1.7``, ``0``, ``-5``, ``nan``, ``inf``, ``fast``, an
Arabic-Indic digit, which ``float`` would read as a number) is one line naming
the manifest, the line and the value, never read as something else: a speed of
``nan`` would place every order line nowhere, a speed of 0 divide by zero.
"""

from __future__ import annotations

import math

from ..errors import SDTError
from ..signals.tokens import quote
from ..specs import MachineSpec

__all__ = ["severity_cell", "speed_fields", "speed_rpm_cell"]


def _float(text: str) -> float:
    """``text`` as a float (ASCII only: ``float("٣")`` would be 3), NaN when it is none."""
    try:
        return float(text) if text.isascii() else math.nan
    except ValueError:
        return math.nan


def severity_cell(where: str, text: str) -> int | None:
    """An integer level, or None when empty; 2.0 (Parquet floats) is 2, 1.7 is refused."""
    if not text or text.lower() == "nan":
        return None
    value = _float(text)
    if not (math.isfinite(value) and value == int(value)):
        raise SDTError(
            f"{where}: field 'severity' = {quote(text)} is not an integer; give a whole "
            f"fault level (1, 2, ...) or leave it empty for healthy"
        )
    return int(value)


def speed_rpm_cell(where: str, text: str) -> float | None:
    """The shaft speed in rpm, or None when the cell is empty (not known: the speed may
    then be estimated from the spectrum); anything but a positive finite number is refused."""
    if not text:
        return None
    value = _float(text)
    if not (math.isfinite(value) and value > 0):
        raise SDTError(
            f"{where}: field 'speed_rpm' = {quote(text)} is not a shaft speed; give the "
            f"speed in rpm as a positive number (1480), or leave the cell empty where it is "
            f"not known"
        )
    return value


def speed_fields(
    rpm: float | None, lines: str, machine: MachineSpec | None
) -> dict[str, float | str | None]:
    """A recording's ``speed_rpm``, ``speed_percent`` and ``speed_source`` from its rows'
    ``speed_rpm`` (``lines`` names them); the percentage where ``machine`` (its
    machines.toml entry) gives a rated speed."""
    if rpm is None:
        return {"speed_rpm": None, "speed_percent": None, "speed_source": ""}
    source = f"manifest speed_rpm ({lines})"
    percent = None
    if machine is not None and machine.rated_rpm is not None:
        percent = 100.0 * rpm / machine.rated_rpm
        source += f", % of the rated {machine.rated_rpm:g} rpm in {machine.origin or 'its spec'}"
    return {"speed_rpm": rpm, "speed_percent": percent, "speed_source": source}
