"""NumPy ``.npy`` arrays: 1-D (one acquisition) or 2-D (longer axis is time); no rate held."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.rules import SignalInfo, as_acquisitions, orient, real
from sdt_framework.signals.tokens import brief
from sdt_framework.specs import ReaderSpec


def _load(path: Path, **options: object) -> np.ndarray:
    try:
        data = np.load(path, allow_pickle=False, **options)  # type: ignore[call-overload]
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, EOFError) as exc:
        raise DataFileError(f"{path}: not a readable NPY file ({brief(exc)})") from None
    return real(path, data)


def probe(path: Path, variable: str | None) -> SignalInfo:
    """Shape from the memory-mapped header (no sample is read)."""
    return SignalInfo(None, *orient(path, _load(path, mmap_mode="r").shape))


def scan(path: Path) -> list[SignalInfo]:
    """The array, as one signal."""
    return [probe(path, None)]


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_acquisitions, n_samples), all finite."""
    return as_acquisitions(path, _load(path))


def count(path: Path, variable: str | None) -> int | None:
    """Values in the array, from the header alone (a file too large to map is sized too)."""
    with path.open("rb") as handle:
        version = np.lib.format.read_magic(handle)
        read_header = {
            (1, 0): np.lib.format.read_array_header_1_0,
            (2, 0): np.lib.format.read_array_header_2_0,
        }.get(version)
        if read_header is None:
            return None
        shape = read_header(handle)[0]
    return math.prod(shape)


@hookimpl
def register_signal_readers(register):
    """Register the NPY reader."""
    register(
        ReaderSpec(
            name="npy",
            label="NPY",
            suffixes=(".npy",),
            description="numpy.save arrays of samples in g",
            source="NumPy .npy format",
            sniff=lambda head: head.startswith(b"\x93NUMPY"),
            scan=scan,
            probe=probe,
            read=read,
            count=count,
        )
    )
