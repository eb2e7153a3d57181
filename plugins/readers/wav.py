"""WAV files from portable recorders and sound cards (scipy.io.wavfile): integer PCM or float.

The rate is the header's (the ``fmt`` chunk's sample rate), refused outside
:data:`~sdt_framework.data.readers.RATE_RANGE_HZ` (a header rate of 0 Hz is
a damaged or wrongly written file). A file cut short, inside its header or
its data, is refused naming the bytes it holds. An integer PCM sample is a count, not an
acceleration: the manifest column ``full_scale_g`` (the acceleration, in g,
of a full-scale sample, from the recorder's calibration) is required and a
file without it is refused naming the column. A sample is ``count /
2**(bits-1) * full_scale_g`` (8-bit WAV is unsigned: ``(count - 128) / 128``);
24-bit files are read by scipy as left-justified 32-bit, so the same rule
holds. Float WAV samples are taken in the manifest's units, scaled by
``full_scale_g`` when it is given. Each channel is a signal named ``ch1``,
``ch2``...
"""

from __future__ import annotations

import math
import struct
import warnings
from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, as_acquisitions, checked_rate, pick
from sdt_framework.data.recording import DataFileError
from sdt_framework.data.tokens import brief, quote
from sdt_framework.errors import SDTError
from sdt_framework.specs import ReaderSpec


def _load(path: Path) -> tuple[int, np.ndarray]:
    import scipy.io.wavfile

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", scipy.io.wavfile.WavFileWarning)
            rate, data = scipy.io.wavfile.read(path, mmap=True)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, EOFError, struct.error, scipy.io.wavfile.WavFileWarning) as exc:
        raise DataFileError(_unreadable(path, exc)) from None
    return int(rate), data if data.ndim == 2 else data[:, None]


def _unreadable(path: Path, exc: Exception) -> str:
    """Why scipy could not read the file: cut short (fewer bytes than its RIFF header
    declares), or what scipy says."""
    with open(path, "rb") as handle:
        head = handle.read(12)
        size = handle.seek(0, 2)
    if head[:4] in (b"RIFF", b"RIFX") and len(head) >= 8:
        declared = int.from_bytes(head[4:8], "little" if head[:4] == b"RIFF" else "big") + 8
        if size < declared:
            return (
                f"{path}: truncated: the file holds {size:,} bytes, its RIFF header declares "
                f"{declared:,}; copy it from the recorder again"
            )
    if isinstance(exc, struct.error):  # a header field cut off
        return f"{path}: truncated: the file ends inside its header ({size:,} bytes)"
    return f"{path}: not a readable WAV file (scipy: {brief(exc)}); a copy cut short?"


def _full_scale(path: Path, data: np.ndarray, full_scale_g: str | float | None) -> float | None:
    if full_scale_g in (None, ""):
        if data.dtype.kind in "iu":
            raise SDTError(
                f"{path}: integer PCM ({data.dtype.itemsize * 8}-bit) samples are counts, not "
                f"g; give the recorder's full scale in g in the manifest column 'full_scale_g' "
                f"(sdt dataset manifest --full-scale-g G)"
            )
        return None
    try:
        value = float(full_scale_g)  # type: ignore[arg-type]
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise SDTError(f"{path}: full_scale_g = {quote(str(full_scale_g))} is not a positive g")
    return value


def _infos(path: Path, full_scale_g: str | float | None) -> list[SignalInfo]:
    rate, data = _load(path)
    scale = _full_scale(path, data, full_scale_g)
    units = "g" if scale is not None else None
    kind = f"{'float' if data.dtype.kind == 'f' else 'PCM'} {data.dtype.itemsize * 8}-bit"
    shown, fault = _rate(path, rate)
    return [SignalInfo(f"ch{i + 1}", 1, data.shape[0], shown, units, "header", label=kind,
                       fault=fault) for i in range(data.shape[1])]  # fmt: skip


def _rate(path: Path, rate: int) -> tuple[float | None, str | None]:
    return checked_rate(
        path, float(rate), f"its header's sample rate (fmt chunk) is {rate} Hz",
        "the header is damaged or was written with a wrong rate; export the file again at "
        "the recorder's rate",
    )  # fmt: skip


def scan(path: Path, full_scale_g: str | float | None = None) -> list[SignalInfo]:
    """Every channel (header only); an integer file lists its channels without units."""
    try:
        return _infos(path, full_scale_g)
    except SDTError as exc:
        if isinstance(exc, DataFileError):
            raise
        rate, data = _load(path)
        note = "integer PCM counts: give full_scale_g to read them in g"
        kind = f"PCM {data.dtype.itemsize * 8}-bit"
        shown, fault = _rate(path, rate)
        return [SignalInfo(f"ch{i + 1}", 1, data.shape[0], shown, None, "header", label=kind,
                           note=note, fault=fault) for i in range(data.shape[1])]  # fmt: skip


def probe(path: Path, variable: str | None, full_scale_g: str | float | None = None) -> SignalInfo:
    """Channel ``variable`` (``ch1``...), or the file's only one."""
    return pick(path, _infos(path, full_scale_g), variable)


def read(path: Path, variable: str | None, full_scale_g: str | float | None = None) -> np.ndarray:
    """float64 (1, n_samples) in g (integer PCM) or as stored times ``full_scale_g`` (float)."""
    info = probe(path, variable, full_scale_g)
    _, data = _load(path)
    column = np.asarray(data[:, int(str(info.variable)[2:]) - 1])
    scale = _full_scale(path, data, full_scale_g)
    if column.dtype.kind == "u":  # 8-bit WAV: unsigned, 128 is zero
        values = (column.astype(np.float64) - 128.0) / 128.0
    elif column.dtype.kind == "i":
        values = column.astype(np.float64) / float(2 ** (column.dtype.itemsize * 8 - 1))
    else:
        values = column.astype(np.float64)
    return as_acquisitions(path, values * (1.0 if scale is None else scale))


@hookimpl
def register_signal_readers(register):
    """Register the WAV reader."""
    register(
        ReaderSpec(
            name="wav",
            label="WAV",
            suffixes=(".wav",),
            options=("full_scale_g",),
            description="WAV channels (scipy.io.wavfile); integer PCM needs full_scale_g",
            source="scipy.io.wavfile; RIFF WAVE format",
            sniff=lambda head: head[:4] in (b"RIFF", b"RF64") and head[8:12] == b"WAVE",
            scan=scan,
            probe=probe,
            read=read,
        )
    )
