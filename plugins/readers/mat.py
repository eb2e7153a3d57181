"""MATLAB v5-v7 ``.mat`` files through scipy.io; v7.3 (HDF5) files go to :mod:`.mat73`.

The two share the suffix, so each sniffs the file's header; a headerless v4
file is refused as neither (save it with ``-v7`` or ``-v7.3``).

A variable is a signal when its MATLAB class is numeric: a ``logical`` array
(which scipy reads as 0/1 ``uint8``) is listed and refused when read, as are
text, cells and structs. A 2-D matrix is read with its longer axis as time
(:func:`~sdt_framework.data.readers.orient`): an N x 3 matrix is three
acquisitions of one signal, and a note says so, since its columns may as well
be three axes.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.data.readers import SignalInfo, as_acquisitions, names, orient
from sdt_framework.data.recording import DataFileError, SignalTypeError
from sdt_framework.data.tokens import brief, quote
from sdt_framework.specs import ReaderSpec

#: HDF5's signature, where a MATLAB v7.3 file (512-byte user block) holds it
HDF5_AT_512 = b"\x89HDF\r\n\x1a\n"
#: MATLAB classes of arrays of numbers (``whos``, and the ``MATLAB_class`` of a v7.3 file)
NUMERIC = {"double", "single", "int8", "int16", "int32", "int64", "uint8", "uint16", "uint32",
           "uint64"}  # fmt: skip


def matlab_signal(path: Path, name: str, shape: tuple[int, ...], cls: str) -> SignalInfo:
    """A MATLAB variable as a signal: refused (``fault``) unless numeric, noted when a matrix."""
    n_acq, n_samples = orient(path, shape)
    fault = note = None
    if cls == "logical":
        fault = (
            f"{path}: variable {quote(name)} is a MATLAB logical array (true/false), not "
            f"samples; save the signal as double (in g)"
        )
    elif cls not in NUMERIC:
        fault = f"{path}: variable {quote(name)} is a MATLAB {cls}, not an array of numbers"
    elif len(shape) == 2 and min(shape) > 1:
        axis = "columns" if shape[0] > shape[1] else "rows"
        note = (
            f"{path}: variable {quote(name)} is a {shape[0]:,} x {shape[1]:,} matrix, read as "
            f"{n_acq} acquisitions of one signal ({n_samples:,} samples each, the longer axis "
            f"is time); if its {axis} are different axes or sensors, save each as a variable"
        )
    return SignalInfo(name, n_acq, n_samples, note=note, fault=fault)


def typed(info: SignalInfo) -> SignalInfo:
    """``info`` when it is numbers; else its fault, raised as a :class:`SignalTypeError`: the
    file was read and is not samples, so a run stops (as for a bool ``.npy``)."""
    if info.fault:
        raise SignalTypeError(info.fault)
    return info


def _variables(path: Path) -> dict[str, tuple[tuple[int, ...], str]]:
    import scipy.io

    try:
        return {name: (shape, cls) for name, shape, cls in scipy.io.whosmat(path)}
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{path}: not a readable MATLAB file ({brief(exc)})") from None


def scan(path: Path) -> list[SignalInfo]:
    """Every variable of 1 or 2 dimensions (headers only)."""
    found = _variables(path)
    return [matlab_signal(path, n, s, c) for n, (s, c) in sorted(found.items()) if len(s) in (1, 2)]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The named variable, or the file's only one."""
    found = _variables(path)
    if variable is None:
        if len(found) != 1:
            raise DataFileError(
                f"{path}: holds variables {names(sorted(found))}; name one in 'variable'"
            )
        variable = next(iter(found))
    if variable not in found:
        raise DataFileError(f"{path}: no variable {quote(variable)}; found {names(sorted(found))}")
    shape, cls = found[variable]
    return typed(matlab_signal(path, variable, shape, cls))


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_acquisitions, n_samples), all finite."""
    import scipy.io

    name = probe(path, variable).variable
    try:
        data = scipy.io.loadmat(path, variable_names=[name])[name]
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{path}: not a readable MATLAB file ({brief(exc)})") from None
    return as_acquisitions(path, data)


def sniff(head: bytes) -> bool:
    """A MATLAB v5-v7 file: its 116-byte text header says so (v7.3 goes to :mod:`.mat73`)."""
    return head.startswith(b"MATLAB 5.0") and head[512:520] != HDF5_AT_512


@hookimpl
def register_signal_readers(register):
    """Register the MATLAB v5-v7 reader."""
    register(
        ReaderSpec(
            name="mat",
            label="MATLAB v5",
            suffixes=(".mat",),
            description="MATLAB v5-v7 .mat variables (scipy.io.loadmat)",
            source="scipy.io",
            sniff=sniff,
            scan=scan,
            probe=probe,
            read=read,
        )
    )
