"""What a signal reader returns, and the checks every reader shares.

A reader plugin (:class:`~sdt_framework.specs.ReaderSpec`) describes each
signal of a file as a :class:`SignalInfo`: its manifest ``variable``, shape,
and the rate and units *as the file states them* (None where the format holds
none: NPY, CSV, MAT). The manifest compares those with its own columns, so a
rate or unit that disagrees with the file is an error naming both rather than
a silently wrong benchmark. The helpers here (orientation, real and finite
samples, unit names, choosing a variable) are the rules every reader applies,
so that a format added by a plugin behaves like the built-in ones.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..dtypes import describe_dtype, is_real
from .recording import DataFileError, SignalTypeError
from .tokens import quote

__all__ = [
    "HEADER_RATE_TOLERANCE",
    "SignalInfo",
    "acceleration_units",
    "as_acquisitions",
    "finite",
    "names",
    "orient",
    "pick",
    "rate_from_increment",
    "real",
]

#: relative difference tolerated between a manifest rate and one a file's header states
HEADER_RATE_TOLERANCE = 1e-6

#: the spellings of acceleration units found in DAQ files -> the manifest's unit names
_UNIT_SPELLINGS = {
    "g": "g",
    "gn": "g",
    "g0": "g",
    "mg": "mg",
    "m/s^2": "m/s^2",
    "m/s2": "m/s^2",
    "m/s²": "m/s^2",
    "m/s/s": "m/s^2",
    "m/sec^2": "m/s^2",
    "(m/s)/s": "m/s^2",
    "m s^-2": "m/s^2",
    "m*s^-2": "m/s^2",
}


@dataclass(frozen=True)
class SignalInfo:
    """One signal of a file as its reader sees it, before any sample is converted.

    ``variable`` is what a manifest's ``variable`` column names it by (None:
    the file's only signal). ``rate_hz`` and ``units`` are the file's own (None
    when it holds none); ``rate_from`` names the field they came from
    (``wf_increment``, ``Delta_X``, ``header``, ``timestamps``) and
    ``rate_tolerance`` the relative difference a manifest may have from it.
    """

    variable: str | None
    n_acquisitions: int
    n_samples: int
    rate_hz: float | None = None
    units: str | None = None
    rate_from: str = ""
    rate_tolerance: float = HEADER_RATE_TOLERANCE
    label: str = ""
    note: str | None = None

    @property
    def shape(self) -> tuple[int, int]:
        """(n_acquisitions, n_samples)."""
        return self.n_acquisitions, self.n_samples

    @property
    def duration_s(self) -> float | None:
        """Length of one acquisition, s (None without a rate)."""
        return None if not self.rate_hz else self.n_samples / self.rate_hz

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready form, with the duration."""
        return {**asdict(self), "duration_s": self.duration_s}


def acceleration_units(units: str | None) -> str | None:
    """The manifest's name (``g``, ``mg``, ``m/s^2``) for a unit string from a file, or None
    when it is not one of those (a voltage, a force, an empty label)."""
    if units is None:
        return None
    key = " ".join(units.strip().split()).lower().replace("**", "^")
    return _UNIT_SPELLINGS.get(key)


def rate_from_increment(file: Path, increment: Any, field: str) -> float:
    """1 / ``increment``, refusing a missing, zero, negative or non-finite increment by name."""
    try:
        value = float(increment)
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise DataFileError(
            f"{file}: its {field} is {quote(str(increment))}, not a positive time step, so the "
            f"sampling rate cannot be read from it"
        )
    return 1.0 / value


def names(found: list[str]) -> str:
    """At most 8 names, each a short token (names come from the file)."""
    return ", ".join(quote(n) for n in found[:8]) + (", ..." if len(found) > 8 else "")


def pick(file: Path, infos: list[SignalInfo], variable: str | None) -> SignalInfo:
    """The signal a manifest row names: ``variable``, or the file's only signal."""
    if variable is None:
        if len(infos) == 1:
            return infos[0]
        if not infos:
            raise DataFileError(f"{file}: holds no signal to read")
        found = [str(i.variable) for i in infos]
        raise DataFileError(f"{file}: holds signals {names(found)}; name one in 'variable'")
    for info in infos:
        if info.variable == variable:
            return info
    found = [str(i.variable) for i in infos]
    raise DataFileError(f"{file}: no signal {quote(variable)}; it holds {names(found)}")


def orient(file: Path, shape: tuple[int, ...]) -> tuple[int, int]:
    """(n_acquisitions, n_samples) of an array: 1-D is one acquisition, 2-D's longer axis is
    time (MATLAB users store columns, numpy users rows)."""
    if len(shape) == 1:
        return 1, shape[0]
    if len(shape) == 2:
        return (shape[1], shape[0]) if shape[0] > shape[1] else (shape[0], shape[1])
    raise DataFileError(f"{file}: array of shape {shape}; expected 1-D or 2-D")


def real(file: Path, data: np.ndarray) -> np.ndarray:
    """``data`` if it holds real numbers; booleans, complex, text... are refused by name."""
    if not is_real(data.dtype):
        raise SignalTypeError(
            f"{file}: holds {describe_dtype(data.dtype)}, not real numbers; save the signal "
            f"as int or float samples in g (nothing is converted for you)"
        )
    return data


def as_acquisitions(file: Path, data: np.ndarray) -> np.ndarray:
    """A 1-D or 2-D real array as float64 (n_acquisitions, n_samples), all finite."""
    data = np.asarray(real(file, np.asarray(data)), dtype=np.float64)
    orient(file, data.shape)  # rejects 0-D and >2-D arrays
    if data.ndim == 2 and 1 in data.shape:
        data = data.reshape(-1)
    if data.ndim == 1:
        data = data[None, :]
    elif data.shape[0] > data.shape[1]:
        data = data.T
    return finite(file, np.ascontiguousarray(data))


def finite(file: Path, data: np.ndarray, unit: str = "sample", offset: int = 0) -> np.ndarray:
    """``data`` (rows, samples) if every value is finite; else the first bad one, named."""
    bad = ~np.isfinite(data)
    if bad.any():
        acq, sample = np.argwhere(bad)[0]
        raise DataFileError(
            f"{file}: acquisition {acq}, {unit} {sample + offset}: "
            f"non-finite value {data[acq, sample]!r}"
        )
    return data
