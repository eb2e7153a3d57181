"""MATLAB v5-v7 ``.mat`` files through scipy.io; v7.3 (HDF5) files go to :mod:`.mat73`.

The two share the suffix, so each sniffs the file's header; a headerless v4
file is refused as neither (save it with ``-v7`` or ``-v7.3``).

A variable is a signal when its MATLAB class is numeric: a ``logical`` array
(which scipy reads as 0/1 ``uint8``) is listed and refused when read, as are
text, cells and structs. A 2-D matrix is read with its longer axis as time
(:func:`~sdt_framework.signals.rules.orient`): an N x 3 matrix is three
acquisitions of one signal, and a note says so, since its columns may as well
be three axes.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import replace
from pathlib import Path

import numpy as np

from sdt_framework import hookimpl
from sdt_framework.signals.errors import DataFileError, SignalTypeError
from sdt_framework.signals.rules import SignalInfo, as_acquisitions, names, orient
from sdt_framework.signals.tokens import brief, quote
from sdt_framework.specs import ReaderSpec

#: HDF5's signature, where a MATLAB v7.3 file (512-byte user block) holds it
HDF5_AT_512 = b"\x89HDF\r\n\x1a\n"
#: MATLAB classes of arrays of numbers (``whos``, and the ``MATLAB_class`` of a v7.3 file)
NUMERIC = {"double", "single", "int8", "int16", "int32", "int64", "uint8", "uint16", "uint32",
           "uint64"}  # fmt: skip


def _fault(path: Path, name: str, shape: tuple[int, ...], cls: str, why: str | None) -> str | None:
    """Why a MATLAB variable is not a signal, or None when it is one."""
    what = f"{path}: variable {quote(name)}"
    size = " x ".join(f"{n:,}" for n in shape)
    if why == "empty" or 0 in shape:
        return f"{what} is an empty MATLAB {cls} array ({size}): no samples"
    if why == "complex":
        return f"{what} is complex ({cls}); sdt reads real samples: save real(x) as a variable"
    if why == "sparse":
        return f"{what} is a MATLAB sparse matrix; save full(x) as a variable"
    if why is not None and why != "class":  # a struct or cell: what it holds
        return f"{what} is a MATLAB {cls} that {why}"
    if cls == "logical":
        return (
            f"{what} is a MATLAB logical array (true/false), not samples; save the signal as "
            f"double (in g)"
        )
    if cls not in NUMERIC:
        return (
            f"{what} is a MATLAB {cls}, not an array of numbers; sdt reads numeric arrays (in a "
            f"v7.3 file also inside structs and cells: 's.f', 'c{{1}}')"
        )
    if len(shape) > 2:
        return f"{what} is a {size} array; sdt reads 1-D and 2-D arrays: save it as a matrix"
    return None


def matlab_signal(
    path: Path, name: str, shape: tuple[int, ...], cls: str, why: str | None = None
) -> SignalInfo:
    """A MATLAB variable as a signal: refused (``fault``) unless a numeric array of values
    (``why`` is a reader's reason it is not: ``empty``, ``complex``, ``sparse``, or what a
    struct or cell holds); noted when a matrix."""
    fault = _fault(path, name, shape, cls, why)
    if fault is not None or len(shape) not in (1, 2):
        longest = max(shape, default=0)
        return SignalInfo(name, 1 if not longest else math.prod(shape) // longest, longest,
                          fault=fault)  # fmt: skip
    n_acq, n_samples = orient(path, shape)
    note = None
    if len(shape) == 2 and min(shape) > 1:
        axis = "columns" if shape[0] > shape[1] else "rows"
        note = (
            f"{path}: variable {quote(name)} is a {shape[0]:,} x {shape[1]:,} matrix, read as "
            f"{n_acq} acquisitions of one signal ({n_samples:,} samples each, the longer axis "
            f"is time); if its {axis} are different axes or sensors, save each as a variable"
        )
    return SignalInfo(name, n_acq, n_samples, note=note)


def typed(info: SignalInfo) -> SignalInfo:
    """``info`` when it is numbers; else its fault, raised as a :class:`SignalTypeError`: the
    file was read and is not samples, so a run stops (as for a bool ``.npy``). An empty array
    holds no samples, which is a :class:`DataFileError` (its manifest row is skipped), as for
    any reader's empty signal."""
    if info.fault and (info.n_samples == 0 or info.n_acquisitions == 0):
        raise DataFileError(info.fault)
    if info.fault:
        raise SignalTypeError(info.fault)
    return info


def _variables(path: Path) -> tuple[dict[str, tuple[tuple[int, ...], str]], dict[str, int]]:
    """({name: (shape, class) of its last copy}, {name: copies} of names stored more than once)."""
    import scipy.io

    try:
        listed = scipy.io.whosmat(path)
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{path}: not a readable MATLAB file ({brief(exc)})") from None
    copies = Counter(name for name, _, _ in listed)
    return {name: (shape, cls) for name, shape, cls in listed}, {
        name: n for name, n in copies.items() if n > 1
    }


def _signal(path: Path, name: str, found: dict, copies: dict[str, int]) -> SignalInfo:
    info = matlab_signal(path, name, *found[name])
    if name not in copies:
        return info
    said = (
        f"{path}: variable {quote(name)} is stored {copies[name]} times (a writer that appends "
        f"rather than replaces); read as its last copy, the one scipy.io.loadmat keeps"
    )
    return replace(info, note=said if info.note is None else f"{said}; {info.note}")


def scan(path: Path) -> list[SignalInfo]:
    """Every variable (headers only), each name once; one that is not a 1-D or 2-D numeric
    array is listed with the reason."""
    found, copies = _variables(path)
    return [_signal(path, name, found, copies) for name in sorted(found)]


def probe(path: Path, variable: str | None) -> SignalInfo:
    """The named variable, or the file's only one."""
    return _probe(path, variable)[0]


def _probe(path: Path, variable: str | None) -> tuple[SignalInfo, bool]:
    """(the signal, whether its name is stored more than once)."""
    found, copies = _variables(path)
    if variable is None:
        if len(found) != 1:
            raise DataFileError(
                f"{path}: holds variables {names(sorted(found))}; name one in 'variable'"
            )
        variable = next(iter(found))
    if variable not in found:
        raise DataFileError(f"{path}: no variable {quote(variable)}; found {names(sorted(found))}")
    return typed(_signal(path, variable, found, copies)), variable in copies


def _last_copy(path: Path, name: str) -> np.ndarray:
    """The last of several variables named ``name``: ``loadmat(variable_names=...)`` stops at
    the first, so the file is split into its variables (``varmats_from_mat``, scipy's own
    answer to duplicate names) and the last is read."""
    from scipy.io.matlab import loadmat, varmats_from_mat

    with open(path, "rb") as handle:
        last = [stream for found, stream in varmats_from_mat(handle) if found == name][-1]
    return loadmat(last)[name]


def read(path: Path, variable: str | None) -> np.ndarray:
    """float64 (n_acquisitions, n_samples), all finite; a name stored twice is its last copy."""
    import scipy.io

    info, copied = _probe(path, variable)
    name = str(info.variable)
    try:
        if copied:
            data = _last_copy(path, name)
        else:
            data = scipy.io.loadmat(path, variable_names=[name])[name]
    except OSError as exc:
        raise DataFileError(f"{path}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{path}: not a readable MATLAB file ({brief(exc)})") from None
    return as_acquisitions(path, data)


def count(path: Path, variable: str | None) -> int | None:
    """Values in the file's arrays (or ``variable``'s), from the list of its variables."""
    from scipy.io import whosmat

    found = [(name, shape) for name, shape, _ in whosmat(str(path))]
    if variable is not None:
        found = [(name, shape) for name, shape in found if name == variable]
    return sum(math.prod(shape) for _, shape in found) or None


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
            count=count,
        )
    )
