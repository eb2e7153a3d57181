"""MATLAB v7.3 ``.mat`` files, which are HDF5 (``scipy.io.loadmat`` refuses them), through h5py.

A v7.3 file is an HDF5 file behind a 512-byte text header. Every numeric
array is a signal: a top-level variable, a struct's field (``s.f``), a cell's
element (``c{2}``), a struct array's field (``s(3).f``), named as MATLAB
writes the expression (:mod:`.mat73_tree`). MATLAB writes arrays column-major,
so h5py sees them transposed; the longer axis is time either way
(:func:`~sdt_framework.signals.rules.orient`); a matrix is noted (in MATLAB's
row x column order). A top-level variable that is not a signal is listed with
the reason (as in :mod:`.mat`): a ``logical`` array, an empty one (MATLAB
stores ``[]`` as its dimensions), a complex or sparse one, text, or a struct
or cell holding no numbers (naming its fields).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.signals.errors import DataFileError
from sdt_framework.signals.rules import SignalInfo, as_acquisitions, pick
from sdt_framework.signals.tokens import brief, quote
from sdt_framework.specs import ReaderSpec

from .mat import HDF5_AT_512, matlab_signal, typed
from .mat73_tree import arrays


def _open(path: Path):
    import h5py

    try:
        return h5py.File(path, "r")
    except OSError as exc:
        raise DataFileError(
            f"{path}: not a readable MATLAB v7.3 (HDF5) file ({brief(exc)}); a copy cut short?"
        ) from None


def _signals(path: Path, handle) -> dict[str, tuple[SignalInfo, object]]:
    """{MATLAB name: (its signal, the dataset holding it)} for every array of the file."""
    return {
        a.name: (matlab_signal(path, a.name, a.shape, a.cls, a.why), a.dataset)
        for a in arrays(handle)
    }


def scan(path: Path) -> list[SignalInfo]:
    """Every variable, struct field and cell element holding numbers (headers only); a
    top-level variable that is not a signal is listed with the reason."""
    with _open(path) as handle:
        return [info for info, _ in _signals(path, handle).values()]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The named variable (``x``, ``s.f``, ``c{2}``, ``s(3).f``), or the file's only one."""
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
            data = _signals(path, handle)[str(name)][1][()]  # type: ignore[index]
        except (OSError, KeyError) as exc:
            raise DataFileError(
                f"{path}: variable {quote(str(name))} unreadable ({brief(exc)})"
            ) from None
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
