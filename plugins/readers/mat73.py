"""MATLAB v7.3 ``.mat`` files, which are HDF5 (``scipy.io.loadmat`` refuses them), through h5py.

A v7.3 file is an HDF5 file behind a 512-byte text header; each top-level
dataset with a numeric ``MATLAB_class`` attribute is a variable. MATLAB writes
arrays column-major, so h5py sees them transposed; the longer axis is time
either way (:func:`~sdt_framework.data.readers.orient`); a matrix is noted (in
MATLAB's row x column order) and a ``logical`` array refused as in :mod:`.mat`.
Structs, cells and strings are not signals and are not listed.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, as_acquisitions, pick
from sdt_framework.data.recording import DataFileError
from sdt_framework.data.tokens import brief
from sdt_framework.specs import ReaderSpec

from .mat import HDF5_AT_512, NUMERIC, matlab_signal, typed


def _open(path: Path):
    import h5py

    try:
        return h5py.File(path, "r")
    except OSError as exc:
        raise DataFileError(
            f"{path}: not a readable MATLAB v7.3 (HDF5) file ({brief(exc)}); a copy cut short?"
        ) from None


def _class(dataset) -> str:
    value = dataset.attrs.get("MATLAB_class", b"")
    return value.decode() if isinstance(value, bytes) else str(value)


def scan(path: Path) -> list[SignalInfo]:
    """Every numeric or logical variable of 1 or 2 dimensions (headers only)."""
    import h5py

    with _open(path) as handle:
        return [
            matlab_signal(path, name, item.shape[::-1], _class(item))  # MATLAB order
            for name, item in sorted(handle.items())
            if isinstance(item, h5py.Dataset)
            and _class(item) in NUMERIC | {"logical"}
            and item.ndim in (1, 2)
        ]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The named variable, or the file's only one."""
    infos = scan(path)
    for info in infos:
        if info.variable == variable or (variable is None and len(infos) == 1):
            return typed(info)
    return pick(path, infos, variable)  # refused, naming what the file holds


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_acquisitions, n_samples), all finite."""
    name = probe(path, variable).variable
    with _open(path) as handle:
        try:
            data = handle[name][()]
        except (OSError, KeyError) as exc:
            raise DataFileError(f"{path}: variable {name!r} unreadable ({brief(exc)})") from None
    return as_acquisitions(path, data)


def sniff(head: bytes) -> bool:
    """A v7.3 header, or HDF5's signature after a 512-byte user block."""
    return head.startswith(b"MATLAB 7.3") or head[512:520] == HDF5_AT_512


@hookimpl
def register_signal_readers(register):
    """Register the MATLAB v7.3 reader."""
    register(
        ReaderSpec(
            name="mat73",
            label="MATLAB v7.3",
            suffixes=(".mat",),
            description="MATLAB v7.3 (HDF5) .mat variables (h5py)",
            source="h5py; MATLAB MAT-file v7.3 format",
            sniff=sniff,
            scan=scan,
            probe=probe,
            read=read,
        )
    )
