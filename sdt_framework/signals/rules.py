"""What a signal reader returns, and the checks every reader shares.

A reader plugin (:class:`~sdt_framework.specs.ReaderSpec`) describes each
signal of a file as a :class:`SignalInfo`: its manifest ``variable``, shape,
and the rate and units *as the file states them* (None where the format holds
none: NPY, CSV, MAT). The manifest compares those with its own columns, so a
rate or unit that disagrees with the file is an error naming both rather than
a silently wrong benchmark. The helpers here (orientation, real and finite
samples, unit names, choosing a variable, the range of rates a file may state)
are the rules every reader applies, so that a format added by a plugin behaves
like the built-in ones.

A signal the reader lists but that cannot be read as it stands (a rate outside
:data:`RATE_RANGE_HZ`, a rate or unit that changes within the channel, no
samples) carries its ``fault``: ``sdt dataset inspect`` lists it with a
warning (a slow temperature channel does not hide the accelerometers beside
it), and :func:`pick`, through which every ``probe`` and ``read`` goes, refuses
it with that one line.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np

from ..dtypes import describe_dtype, is_real
from ..units import acceleration_units
from .errors import DataFileError, SignalTypeError
from .tokens import quote, shown

__all__ = [
    "HEADER_RATE_TOLERANCE",
    "RATE_RANGE_HZ",
    "SignalInfo",
    "acceleration_units",
    "as_acquisitions",
    "checked_rate",
    "fault_of",
    "finite",
    "increment_rate",
    "names",
    "note_unstated_units",
    "orient",
    "pick",
    "rate_from_increment",
    "real",
]

#: relative difference tolerated between a manifest rate and one a file's header states
HEADER_RATE_TOLERANCE = 1e-6
#: rates a file may state, Hz: the first third-octave band (10 Hz) needs 25 Hz; no
#: accelerometer DAQ samples above 10 MHz (the twin's pairs are held to the same range)
RATE_RANGE_HZ = (25.0, 1e7)


@dataclass(frozen=True)
class SignalInfo:
    """One signal of a file as its reader sees it, before any sample is converted.

    ``variable`` is what a manifest's ``variable`` column names it by (None:
    the file's only signal). ``rate_hz`` and ``units`` are the file's own (None
    when it holds none); ``rate_from`` names the field they came from
    (``wf_increment``, ``Delta_X``, ``header``, ``timestamps``) and
    ``rate_tolerance`` the relative difference a manifest may have from it.
    ``fault`` is why the signal cannot be read as it stands (one line naming the
    file and the field), None when it can. ``units_field`` names the field a
    format states units in (``unit_string``, ``Y_Unit_Label``), "" for a format
    that has none (NPY, CSV, MAT): a signal with a ``units_field`` and no
    ``units`` left that field empty (:attr:`units_stated` is False), and is
    read in the manifest's units, g where it gives none.
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
    fault: str | None = None
    units_field: str = ""

    @property
    def units_stated(self) -> bool | None:
        """Whether the file states this signal's units; None for a format that holds none."""
        return None if not self.units_field else self.units is not None

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
        return {**asdict(self), "duration_s": self.duration_s, "units_stated": self.units_stated}


def checked_rate(file: Path, rate: float, stated: str, fix: str) -> tuple[float | None, str | None]:
    """(rate, None) for a rate within :data:`RATE_RANGE_HZ`; else (the rate, or None when not
    positive, and why). ``stated`` says where it comes from (``its header's sample rate is
    0 Hz``), ``fix`` what to do."""
    lo, hi = RATE_RANGE_HZ
    if math.isfinite(rate) and lo <= rate <= hi:
        return rate, None
    shown = rate if math.isfinite(rate) and rate > 0 else None
    return shown, (
        f"{file}: {stated}, outside {lo:g} Hz to {hi / 1e6:g} MHz, the rates sdt reads; {fix}"
    )


def increment_rate(file: Path, increment: Any, field: str) -> tuple[float | None, str | None]:
    """(1 / ``increment``, None), or (None or the rate, why) for a missing, zero, negative or
    non-finite increment, or one whose rate is outside :data:`RATE_RANGE_HZ`."""
    try:
        value = float(increment)
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        return None, (
            f"{file}: its {field} is {quote(str(increment))}, not a positive time step, so the "
            f"sampling rate cannot be read from it"
        )
    stated = f"its {field} is {value:.6g} s, a rate of {1.0 / value:.6g} Hz"
    return checked_rate(file, 1.0 / value, stated, "check that field (a time step in seconds)")


def rate_from_increment(file: Path, increment: Any, field: str) -> float:
    """1 / ``increment``; a missing, zero, negative or non-finite increment, or a rate outside
    :data:`RATE_RANGE_HZ`, is refused by name (:func:`increment_rate` for a per-signal fault)."""
    rate, fault = increment_rate(file, increment, field)
    if fault is not None or rate is None:
        raise DataFileError(fault or f"{file}: no rate in its {field}")
    return rate


def fault_of(file: Path, info: SignalInfo) -> str | None:
    """Why ``info`` cannot be read: its reader's ``fault``, or no samples at all."""
    if info.fault:
        return info.fault
    if info.n_samples == 0 or info.n_acquisitions == 0:
        name = "its signal" if info.variable is None else f"signal {quote(info.variable)}"
        return f"{file}: {name} holds no samples (an empty recording); give a file with data"
    return None


def note_unstated_units(file: Path, infos: list[SignalInfo]) -> list[SignalInfo]:
    """``infos``, each readable signal whose file left its units field empty carrying one note
    for the file that names them: they are read in the manifest's units, g where it gives none."""
    unstated = [i for i in infos if i.units_stated is False and not i.fault]
    if not unstated:
        return infos
    chosen, field = {id(i) for i in unstated}, unstated[0].units_field
    which = ", ".join(quote(i.variable, 100) for i in unstated[:8])
    which += f" and {len(unstated) - 8} more" if len(unstated) > 8 else ""
    what = f"signal {which} states" if len(unstated) == 1 else f"signals {which} state"
    note = (
        f"{file}: {what} no units (its {field} is empty): read in the manifest's units, g "
        f"where it gives none; check that they are"
    )
    return [
        replace(i, note="; ".join(filter(None, (i.note, note)))) if id(i) in chosen else i
        for i in infos
    ]


def names(found: list[str]) -> str:
    """At most 8 names, each a short token (names come from the file)."""
    return ", ".join(quote(n) for n in found[:8]) + (", ..." if len(found) > 8 else "")


def pick(file: Path, infos: list[SignalInfo], variable: str | None) -> SignalInfo:
    """The signal a manifest row names: ``variable``, or the file's only signal; a signal with a
    fault (:func:`fault_of`) is refused with it."""
    if variable is None:
        if len(infos) == 1:
            return _usable(file, infos[0])
        if not infos:
            raise DataFileError(f"{file}: holds no signal to read")
        found = [str(i.variable) for i in infos]
        raise DataFileError(f"{file}: holds signals {names(found)}; name one in 'variable'")
    for info in infos:
        if info.variable == variable:
            return _usable(file, info)
    found = [str(i.variable) for i in infos]
    raise DataFileError(f"{file}: no signal {quote(variable)}; it holds {names(found)}")


def _usable(file: Path, info: SignalInfo) -> SignalInfo:
    fault = fault_of(file, info)
    if fault:
        raise DataFileError(fault)
    return info


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
            f"non-finite value {shown(data[acq, sample])}"
        )
    return data
