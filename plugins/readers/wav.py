"""WAV files from portable recorders and sound cards, read with libsndfile (python-soundfile).

Integer PCM of 8 to 32 bits (24-bit and 20-bit in 3-byte containers as
recorders write them) and 32/64-bit float; RIFF, big-endian RIFX, RF64 and
WAVE_FORMAT_EXTENSIBLE headers; any extra chunk (``PEAK``, Broadcast WAV
``bext``, ``LIST``) is skipped. The rate is the header's (the ``fmt`` chunk's
sample rate), refused outside :data:`~sdt_framework.signals.rules.RATE_RANGE_HZ`.
A compressed encoding (u-law, ADPCM...) is refused: it is not the recorded
signal. A file shorter than its RIFF header declares was cut short and is
refused, naming both sizes (libsndfile would read what is left).

An integer PCM sample is a count, not an acceleration: the manifest column
``full_scale_g`` (the acceleration, in g, of a full-scale sample, from the
recorder's calibration) is required and a file without it is refused naming the
column. Samples sit left-justified in their container, so a sample is ``count
/ 2**(bits-1) * full_scale_g`` with ``bits`` the container's (8-bit WAV is
unsigned: ``(count - 128) / 128``); libsndfile hands every integer encoding out
as a left-justified int32, which is divided by 2**31: the same rule, exactly.
Float samples are taken in the manifest's units, scaled by ``full_scale_g``
when it is given. Each channel is a signal named ``ch1``, ``ch2``...

Why libsndfile and not ``scipy.io.wavfile``: scipy reads 3-byte containers
only without memory mapping, by copying the whole file twice (about 2.3 bytes
of memory per byte of file) even to list its channels, and it has no call that
reads a header alone; libsndfile reads the header alone (``inspect`` and
``manifest`` open no sample), reads any encoding in blocks of
:data:`BLOCK_FRAMES`, and has been kept since 1999. The tests read every file
with scipy too and compare the values exactly.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.errors import SDTError
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.rules import SignalInfo, as_acquisitions, checked_rate, pick
from sdt_framework.signals.tokens import brief, quote
from sdt_framework.specs import ReaderSpec

#: frames read at a time: one block of every channel (8 channels: 4 MB as int32 or 8 MB float)
BLOCK_FRAMES = 131_072
#: libsndfile's encodings sdt reads -> the bits of their container
CONTAINER_BITS = {"PCM_U8": 8, "PCM_S8": 8, "PCM_16": 16, "PCM_24": 24, "PCM_32": 32,
                  "FLOAT": 32, "DOUBLE": 64}  # fmt: skip
#: the first four bytes of each WAV header, and the byte order of its fields
_SIGNATURES = {b"RIFF": "little", b"RIFX": "big", b"RF64": "little"}


def _declared_size(path: Path) -> tuple[int, int | None]:
    """(the file's size, the size its RIFF header declares, or None when it declares none)."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(28)
            size = handle.seek(0, 2)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    order = _SIGNATURES.get(head[:4])
    if order is None or len(head) < 8:
        return size, None
    if head[:4] == b"RF64":  # the real size is in the ds64 chunk that follows
        return size, int.from_bytes(head[20:28], "little") + 8 if len(head) >= 28 else None
    return size, int.from_bytes(head[4:8], order) + 8


def _whole(path: Path) -> None:
    """Refuse a file shorter than its RIFF header declares: it was cut short."""
    size, declared = _declared_size(path)
    if declared is not None and size < declared:
        raise DataFileError(
            f"{path}: truncated: the file holds {size:,} bytes, its RIFF header declares "
            f"{declared:,}; copy it from the recorder again"
        )


def _header_rate(path: Path) -> int | None:
    """The ``fmt`` chunk's sample rate, found by walking the chunks (only to say why
    libsndfile refused a header: it names no field)."""
    with open(path, "rb") as handle:
        raw = handle.read(65_536)
    order = _SIGNATURES.get(raw[:4], "little")
    pos = 12
    while pos + 16 <= len(raw):
        tag, size = raw[pos : pos + 4], int.from_bytes(raw[pos + 4 : pos + 8], order)
        if tag == b"fmt ":
            return int.from_bytes(raw[pos + 12 : pos + 16], order)
        pos += 8 + size + (size & 1)
    return None


def _info(path: Path):
    """libsndfile's view of the header (no sample is read)."""
    import soundfile

    _whole(path)
    try:
        info = soundfile.info(str(path))
    except soundfile.LibsndfileError as exc:
        rate = _header_rate(path)
        if rate is not None and _rate(path, rate)[1]:
            raise DataFileError(str(_rate(path, rate)[1])) from None
        reason = brief(RuntimeError(getattr(exc, "error_string", "") or exc))
        raise DataFileError(
            f"{path}: not a readable WAV file (libsndfile: {reason}); sdt reads integer PCM of "
            f"8 to 32 bits and 32/64-bit float (RIFF, RIFX or RF64)"
        ) from None
    if info.subtype not in CONTAINER_BITS:
        raise DataFileError(
            f"{path}: its samples are {info.subtype_info} ({info.subtype}), a compressed or "
            f"unusual encoding, not the recorded signal; sdt reads integer PCM (8 to 32 bits) "
            f"and float WAV: export the recording again as 24-bit PCM or 32-bit float"
        )
    return info


def _integer(info) -> bool:
    return info.subtype.startswith("PCM")


def _full_scale(path: Path, info, full_scale_g: str | float | None) -> float | None:
    if full_scale_g in (None, ""):
        if _integer(info):
            raise SDTError(
                f"{path}: integer PCM ({CONTAINER_BITS[info.subtype]}-bit) samples are counts, "
                f"not g; give the recorder's full scale in g in the manifest column "
                f"'full_scale_g' (sdt dataset manifest --full-scale-g G)"
            )
        return None
    try:
        value = float(full_scale_g)  # type: ignore[arg-type]
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise SDTError(f"{path}: full_scale_g = {quote(str(full_scale_g))} is not a positive g")
    return value


def _rate(path: Path, rate: int) -> tuple[float | None, str | None]:
    return checked_rate(
        path, float(rate), f"its header's sample rate (fmt chunk) is {rate} Hz",
        "the header is damaged or was written with a wrong rate; export the file again at "
        "the recorder's rate",
    )  # fmt: skip


def _signals(path: Path, info, units: str | None, note: str | None) -> list[SignalInfo]:
    kind = f"{'PCM' if _integer(info) else 'float'} {CONTAINER_BITS[info.subtype]}-bit"
    shown, fault = _rate(path, info.samplerate)
    return [SignalInfo(f"ch{i + 1}", 1, info.frames, shown, units, "header", label=kind,
                       note=note, fault=fault) for i in range(info.channels)]  # fmt: skip


def scan(path: Path, full_scale_g: str | float | None = None) -> list[SignalInfo]:
    """Every channel (header only); an integer file without ``full_scale_g`` lists its
    channels without units, noting why."""
    info = _info(path)
    try:
        scale = _full_scale(path, info, full_scale_g)
    except SDTError:
        if full_scale_g not in (None, ""):
            raise
        note = "integer PCM counts: give full_scale_g to read them in g"
        return _signals(path, info, None, note)
    return _signals(path, info, "g" if scale is not None else None, None)


def probe(path: Path, variable: str | None, full_scale_g: str | float | None = None) -> SignalInfo:
    """Channel ``variable`` (``ch1``...), or the file's only one."""
    info = _info(path)
    scale = _full_scale(path, info, full_scale_g)
    return pick(path, _signals(path, info, "g" if scale is not None else None, None), variable)


def read(path: Path, variable: str | None, full_scale_g: str | float | None = None) -> np.ndarray:
    """float64 (1, n_samples) in g (integer PCM) or as stored times ``full_scale_g`` (float),
    read in blocks of :data:`BLOCK_FRAMES` frames: memory is the channel's samples plus one
    block."""
    import soundfile

    channel = int(str(probe(path, variable, full_scale_g).variable)[2:]) - 1
    info = _info(path)
    scale = _full_scale(path, info, full_scale_g)
    integer = _integer(info)
    values = np.empty(info.frames)
    block = np.empty((min(BLOCK_FRAMES, max(info.frames, 1)), info.channels),
                     dtype=np.int32 if integer else np.float64)  # fmt: skip
    done = 0
    with soundfile.SoundFile(str(path)) as handle:
        while done < info.frames:
            got = handle.read(len(block), out=block)
            if len(got) == 0:
                break
            values[done : done + len(got)] = got[:, channel]
            done += len(got)
    if done != info.frames:
        raise DataFileError(
            f"{path}: truncated: its data holds {done:,} frames, its header {info.frames:,}; "
            f"copy it from the recorder again"
        )
    if integer:
        values /= 2.0**31  # left-justified int32: count / 2**(bits-1), exactly
    if scale is not None:
        values *= scale
    return as_acquisitions(path, values)


@hookimpl
def register_signal_readers(register):
    """Register the WAV reader."""
    register(
        ReaderSpec(
            name="wav",
            label="WAV",
            suffixes=(".wav",),
            options=("full_scale_g",),
            description="WAV channels (libsndfile): 8-32-bit PCM needs full_scale_g; float",
            source="python-soundfile (libsndfile); RIFF WAVE, RIFX, RF64",
            sniff=lambda head: head[:4] in _SIGNATURES and head[8:12] == b"WAVE",
            scan=scan,
            probe=probe,
            read=read,
        )
    )
