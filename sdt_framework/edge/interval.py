"""Reporting intervals written as text: ``"10min"``, ``"30s"``, ``"1h"``, ``"1d"``."""

from __future__ import annotations

import math
import re

from ..errors import SDTError

__all__ = ["format_interval", "parse_interval"]

_UNITS = {
    "s": 1.0,
    "sec": 1.0,
    "min": 60.0,
    "h": 3600.0,
    "hr": 3600.0,
    "d": 86400.0,
    "day": 86400.0,
}
_PATTERN = re.compile(r"^\s*(?P<number>\d+(?:\.\d*)?|\.\d+)\s*(?P<unit>[a-z]*)\s*$")


def parse_interval(text: str | float, what: str = "interval") -> float:
    """Seconds in a duration written with its unit, such as ``"10min"``.

    Units: s, sec, min, h, hr, d, day. Text without a unit (``"10"``) is
    refused: ten seconds and ten minutes are both plausible reporting
    intervals, so a guess could be off by 60 times; ``"m"`` is refused as
    ambiguous (minutes or metres?): write ``min``. A Python number is seconds.
    ``what`` names the value in the error (``"interval"``, ``"--window"``).
    """
    if isinstance(text, int | float):
        seconds = float(text)
    else:
        match = _PATTERN.match(str(text).lower())
        if match and not match["unit"]:
            number = match["number"]
            raise SDTError(
                f"{what} {text!r} has no unit; write {number}s (seconds), {number}min, "
                f"{number}h or {number}d"
            )
        if not match or match["unit"] not in _UNITS:
            raise SDTError(f"{what} {text!r} is not a duration; write e.g. 30s, 10min, 1h or 1d")
        seconds = float(match["number"]) * _UNITS[match["unit"]]
    if not (math.isfinite(seconds) and seconds > 0):
        raise SDTError(f"{what} {text!r} must be longer than zero")
    return seconds


def format_interval(seconds: float) -> str:
    """The shortest exact text for ``seconds``: ``600`` -> ``"10min"``."""
    for unit, size in (("d", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size and (seconds / size).is_integer():
            return f"{seconds / size:g}{unit}"
    return f"{seconds:g}s"
