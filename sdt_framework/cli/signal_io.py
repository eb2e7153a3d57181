"""Reading and writing signal arrays for the commands that take a signal file.

A signal file is read through the registered readers, handed down from the
command's registry (:func:`open_input`, :mod:`sdt_framework.signals.one_signal`):
any registered format, with the rate and units the file holds, ``--fs`` only
where it holds none, ``--signal`` where it holds several. Before reading,
:func:`check_signal_size` sizes the job from the file's header (NPY, CSV,
MAT: before a CSV is parsed) and :func:`open_input` from the reader's count
of samples, and a job that cannot fit in the memory available is refused;
:func:`check_pair_size` does the same for a twin pair. Outputs are ``.npy`` or
``.csv``, written atomically (:mod:`sdt_framework.io`); CSV values use
``%.17g`` so a float64 survives the round trip exactly. Every failure is a
one-line :class:`~sdt_framework.errors.SDTError` naming the path.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..errors import SDTError
from ..io import atomic_path
from ..units import TO_G
from ..units import UNITS as ACCELERATION_UNITS
from .common import err_console

if TYPE_CHECKING:
    from ..signals import FileSignal

__all__ = [
    "SUFFIXES",
    "UNITS",
    "check_pair_size",
    "check_signal_size",
    "note",
    "open_input",
    "save_array",
    "to_g",
    "zero_motion_recording",
]

SUFFIXES = (".npy", ".csv")
UNITS = (*ACCELERATION_UNITS, "lsb")


def _suffix(path: Path) -> str:
    suffix = path.suffix.lower()
    if suffix not in SUFFIXES:
        raise SDTError(f"{path}: unsupported file type {suffix or '(none)'!r}; use .npy or .csv")
    return suffix


def note(text: str | None) -> None:
    """Print a reader's note (a dropped time column, a resampled grid) on stderr, plain."""
    if text:
        err_console.print(f"note: {text}", markup=False, highlight=False, soft_wrap=True)


def open_input(
    path: Path,
    readers: Sequence[Any],
    bytes_per_sample: int,
    advice: str,
    **choices: Any,
) -> FileSignal:
    """The signal of ``path`` to read (any registered format), sized against the memory
    available at ``bytes_per_sample``; ``choices`` go to
    :func:`~sdt_framework.signals.one_signal.open_signal` (``signal``, ``rate_hz``, ``units``,
    ``options``, ``default_rate``). The reader's note is printed."""
    from ..signals import open_signal
    from .guards import check_memory

    check_signal_size(path, readers, bytes_per_sample, advice)  # a CSV before it is parsed
    signal = open_signal(path, readers, **choices)
    note(signal.info.note)
    check_memory(path, f"{signal.n_values:,} samples", signal.n_values * bytes_per_sample, advice)
    return signal


def save_array(path: str | os.PathLike[str], x: NDArray[np.float64]) -> Path:
    """Write ``x`` atomically to ``path`` (.npy, or .csv: a 1-D signal as one column)."""
    path = Path(path)
    suffix = _suffix(path)
    with atomic_path(path) as tmp, tmp.open("wb") as handle:
        if suffix == ".npy":
            np.save(handle, x, allow_pickle=False)
        else:
            np.savetxt(handle, x, delimiter=",", fmt="%.17g")
    return path


def zero_motion_recording(
    readers: Sequence[Any],
    path: Path,
    spec: Any,
    axis: str,
    *,
    channel: int | None,
    signal: str | None,
    fs: float | None,
    unit: str | None,
    scale: float | None,
    full_scale_g: float | None,
    reference_fs: float,
) -> tuple[NDArray[np.float64], float]:
    """(samples in g, rate) of ``sdt validate-noise --recording``: through its reader, the
    rate the file's or --fs or the sensor's output rate; of a file of channels (IDE) the
    ``axis`` of the channel of the sensor's part (or --channel) unless --signal names one."""
    from ..chain import compile_chain
    from ..signals import DEGRADE_BYTES_PER_SAMPLE, axis_variable, channel_reader, part_channel

    if unit is not None and unit.lower() not in UNITS:
        raise SDTError(f"--unit {unit!r}: use one of {', '.join(UNITS)}")
    recorder = channel_reader(path, readers)  # a file of channels (IDE): the part's channel
    if channel is not None and (signal is not None or recorder is None):
        raise SDTError(f"{path}: --channel is for an .IDE recording without --signal; drop it")
    if signal is None and recorder is not None:
        listed = recorder.channels(path)[0]
        chosen = part_channel(path, listed, spec.name) if channel is None else channel
        signal = axis_variable(chosen, axis)
    opened = open_input(
        path, readers, DEGRADE_BYTES_PER_SAMPLE, "cut the recording to a shorter stretch",
        signal=signal, rate_hz=fs, units=None if unit is None else unit.lower(),
        options={"full_scale_g": full_scale_g},
        default_rate=(compile_chain(spec, reference_fs).fs_out,
                      "no rate in the file: the sensor's output rate; --fs gives it"),
    )  # fmt: skip
    values = to_g(opened.read(), opened.units, scale, str(path))
    rate, source = opened.rate_hz, opened.rate_from
    note(f"{opened.label}: {opened.n_values:,} samples at {rate:.6g} Hz ({source})")
    return values, rate


def to_g(x: NDArray[np.float64], unit: str, scale: float | None, label: str) -> NDArray[np.float64]:
    """Convert a recording from ``unit`` (g, mg, m/s^2, or raw LSB times ``scale`` g/LSB) to g."""
    if unit in TO_G:
        return x if unit == "g" else x * TO_G[unit]
    if unit == "lsb":
        if scale is None or not scale > 0:
            raise SDTError(f"{label}: --unit lsb needs --scale G_PER_LSB > 0, got {scale}")
        return x * scale
    raise SDTError(f"{label}: unknown unit {unit!r}; use one of {', '.join(UNITS)}")


def check_signal_size(path: Path, readers: Sequence[Any], bytes_per_sample: int,
                      advice: str) -> None:  # fmt: skip
    """Refuse the signal file ``path`` before reading it if its samples (from its header,
    through its reader) at ``bytes_per_sample`` each, plus what its reader's parse takes,
    need more memory than is available."""
    from ..signals import file_samples, reader_for
    from .guards import check_memory

    samples = file_samples(path, readers)
    if samples is not None:
        bytes_per_sample += reader_for(path, readers).parse_bytes_per_value
        check_memory(path, f"{samples:,} samples", samples * bytes_per_sample, advice)


def check_pair_size(pair: Path, readers: Sequence[Any]) -> None:
    """Refuse a paired recording (TOML pair or IDE file) that ``sdt twin check`` cannot hold.

    A TOML pair is sized from its two files' headers, an IDE file from its
    bytes; a pair that cannot be read this way is left to the loader's message.
    """
    from ..signals import TWIN_BYTES_PER_IDE_BYTE, TWIN_BYTES_PER_SAMPLE, file_samples
    from .guards import check_memory

    advice = "cut the recordings to a shorter stretch (a few minutes hold every band)"
    try:
        if pair.suffix.lower() != ".toml":
            size = pair.stat().st_size if pair.is_file() else 0
            check_memory(
                pair, f"{size:,} bytes of recording", size * TWIN_BYTES_PER_IDE_BYTE, advice
            )
            return
        import tomllib

        tables = tomllib.loads(pair.read_text(encoding="utf-8"))
        sides = [tables.get(side) for side in ("reference", "device")]
        files = [(pair.parent / s["file"], s.get("variable")) for s in sides]
    except (OSError, UnicodeError, ValueError, TypeError, KeyError):
        return  # the loader says what is wrong with the file
    counts = [file_samples(file, readers, variable) for file, variable in files]
    if None not in counts:
        samples = sum(c for c in counts if c is not None)
        check_memory(pair, f"{samples:,} samples", samples * TWIN_BYTES_PER_SAMPLE, advice)
