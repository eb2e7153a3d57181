"""One signal of one file, for the commands that take a signal file.

``sdt degrade``, ``sdt features extract``, ``sdt validate-noise --recording``
and a twin pair's sides read their file as a manifest row is read: through the
registered readers, which the caller hands down (``open_signal(file,
registry.signal_readers(), ...)``; this layer never looks a registry up), with
the rate and units the file states. A rate given by the caller (``--fs``, a
pair's ``rate_hz``) is needed only where the file holds none; one that
contradicts the file beyond the reader's tolerance is refused naming both,
since one of them is wrong and everything computed at a wrong rate is wrong. A
file holding several signals is refused, listing them, until one is named
(``--signal``, a pair's ``variable``). Samples in mg or m/s^2 become g; units
that are not an acceleration are refused; a file stating none is in g unless
the caller says otherwise.

Messages name the caller's own options: :data:`CLI_SPELLING` for the command
line, a pair file passes its keys.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..errors import SDTError
from ..inputs import require_regular_file
from ..units import TO_G, units_list
from .errors import DataFileError
from .files import reader_for
from .rules import SignalInfo, acceleration_units, fault_of, names
from .tokens import quote

__all__ = ["CLI_SPELLING", "FileSignal", "open_signal"]

#: how the command line spells the choices a file may need: the signal (with its placeholder),
#: the rate, the units, each reader option
CLI_SPELLING: Mapping[str, str] = {
    "signal": "--signal NAME",
    "rate": "--fs",
    "units": "--unit",
    "full_scale_g": "--full-scale-g",
}


@dataclass(frozen=True)
class FileSignal:
    """A signal chosen in a file, its rate and units settled, its samples not yet read."""

    file: Path
    reader: Any
    info: SignalInfo
    rate_hz: float
    rate_from: str  # "its wf_increment", "--fs"
    units: str  # the samples' unit as read: g, mg, m/s^2, or the caller's own (lsb)
    options: dict[str, Any] = field(default_factory=dict)
    missing: Mapping[str, str] = field(default_factory=dict)  # reader options not given: spelling

    @property
    def label(self) -> str:
        """``file`` or ``file signal 'name'``, for messages."""
        return _label(self.file, self.info.variable)

    @property
    def n_values(self) -> int:
        """Samples in the signal (all acquisitions), for sizing before the read."""
        return self.info.n_acquisitions * self.info.n_samples

    def read(self) -> NDArray[np.float64]:
        """float64 (n_acquisitions, n_samples) in :attr:`units`, all finite."""
        try:
            return self.reader.read(self.file, self.info.variable, **self.options)
        except SDTError as exc:
            raise _hinted(exc, self.missing) from None

    def read_g(self) -> NDArray[np.float64]:
        """float64 (n_acquisitions, n_samples) in g."""
        values = self.read()
        return values if self.units == "g" else values * TO_G[self.units]


def _label(file: Path, variable: str | None) -> str:
    return str(file) if variable is None else f"{file} signal {quote(variable, 60)}"


def _hinted(exc: SDTError, missing: Mapping[str, str]) -> SDTError:
    """``exc``, and how this caller gives each reader option it names (a reader's refusal
    names its manifest column: ``full_scale_g``)."""
    named = [spelled for key, spelled in missing.items() if key in str(exc)]
    if not named:
        return exc
    return type(exc)(f"{exc}; here: give it with {' and '.join(named)}")


def _choose(file: Path, reader: Any, signal: str | None, options: dict, spelling: Mapping,
            missing: Mapping[str, str]) -> SignalInfo:  # fmt: skip
    """The signal ``signal`` names, or the file's only one; several are listed to choose; one
    that cannot be read (no samples, a rate out of range) is refused with why."""
    try:
        info = reader.probe(file, signal, **options)
        fault = fault_of(file, info)
        if fault:
            raise SDTError(fault)
        return info
    except DataFileError as exc:
        if signal is not None:
            raise _hinted(exc, missing) from None
        refused = exc
    except SDTError as exc:
        raise _hinted(exc, missing) from None
    infos = reader.scan(file, **options)
    if len(infos) < 2:
        raise _hinted(refused, missing)
    found = [str(i.variable) for i in infos]
    raise DataFileError(
        f"{file}: holds {len(infos)} signals ({names(found)}); choose one with "
        f"{spelling['signal']} (`sdt dataset inspect {file}` lists them whole)"
    )


def _rate(signal: FileSignal, rate_hz: float | None, default: tuple[float, str] | None,
          spelling: Mapping) -> tuple[float, str]:  # fmt: skip
    """(rate, where it comes from): the file's; else the caller's; else ``default``."""
    info, option = signal.info, spelling["rate"]
    if info.rate_hz is not None:
        if rate_hz is not None and abs(rate_hz / info.rate_hz - 1) > info.rate_tolerance:
            raise SDTError(
                f"{signal.label}: runs at {info.rate_hz:.6g} Hz by its {info.rate_from}, "
                f"{option} says {rate_hz:g} Hz; drop {option} to take the file's rate, or "
                f"check the file (`sdt dataset inspect {signal.file}`)"
            )
        if rate_hz is not None:
            return rate_hz, option
        return info.rate_hz, f"its {info.rate_from}"
    if rate_hz is not None:
        return rate_hz, option
    if default is not None:
        return default
    raise SDTError(
        f"{signal.label}: no sampling rate in this {signal.reader.label} file; give it with "
        f"{option} (Hz)"
    )


def _units(signal: FileSignal, units: str | None, spelling: Mapping) -> str:
    """The samples' unit: the file's (an acceleration), which ``units`` must not contradict;
    else ``units``; else g."""
    stated = signal.info.units
    if stated is None:
        return units or "g"
    known = acceleration_units(stated)
    if known is None:
        raise SDTError(
            f"{signal.label}: the file gives its units as {quote(stated)}, not an acceleration "
            f"({units_list()}); scale the channel to acceleration where it was recorded"
        )
    if units is not None and units != known:
        raise SDTError(
            f"{signal.label}: the file gives its units as {quote(stated)}, "
            f"{spelling['units']} says {units}; drop {spelling['units']} to take the file's units"
        )
    return known


def open_signal(
    file: str | Path,
    readers: Sequence[Any],
    *,
    signal: str | None = None,
    rate_hz: float | None = None,
    units: str | None = None,
    options: Mapping[str, Any] | None = None,
    default_rate: tuple[float, str] | None = None,
    spelling: Mapping[str, str] = CLI_SPELLING,
) -> FileSignal:
    """The signal of ``file`` to read, its rate and units settled (no sample read yet).

    Parameters
    ----------
    readers
        The registered signal readers (``registry.signal_readers()``), handed down.
    signal
        The reader's name of the signal (``GROUP/CHANNEL``, ``ch2``, ``32:x``); None: the
        file's only one.
    rate_hz, units
        The caller's statement of the rate (Hz) and units, checked against the file's.
    options
        Reader options by name (``full_scale_g``); None values are not given.
    default_rate
        (rate, source) used when neither the file nor ``rate_hz`` gives one; None: refused.
    spelling
        How the caller names ``signal``, ``rate``, ``units`` and each reader option.
    """
    file = Path(file)
    require_regular_file(file, "signal file")
    if not file.is_file():
        what = "is a folder; give the signal file" if file.is_dir() else "no such file"
        raise SDTError(f"{file}: {what}; check the path")
    if not readers:
        raise SDTError(
            f"{file}: no signal reader is registered, so no file can be read; check "
            f"SDT_PLUGINS / SDT_BLOCK_PLUGINS (`sdt plugins list`)"
        )
    reader = reader_for(file, readers)
    given = {k: v for k, v in (options or {}).items() if v is not None}
    for key in given:
        if key not in reader.options:
            raise SDTError(
                f"{file}: {spelling.get(key, key)} does not apply to this {reader.label} file; "
                f"drop it"
            )
    missing = {k: spelling.get(k, k) for k in reader.options if k not in given}
    info = _choose(file, reader, signal, given, spelling, missing)
    opened = FileSignal(file, reader, info, 0.0, "", "g", given, missing)
    rate, source = _rate(opened, rate_hz, default_rate, spelling)
    return FileSignal(file, reader, info, rate, source, _units(opened, units, spelling), given,
                      missing)  # fmt: skip
