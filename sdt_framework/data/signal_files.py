"""Read one signal file of a manifest row: CSV, NPY or MATLAB ``.mat``.

Every file becomes a float64 array (n_acquisitions, n_samples). A 1-D signal
is one acquisition. A 2-D array holds several acquisitions; its longer axis is
time (MATLAB users store signals as columns, numpy users as rows, and an
acquisition is always longer than the number of acquisitions). CSV follows the
same rule through :func:`~sdt_framework.data.csv_signal.read_csv_signal`
(header and time column detected; the named column, or every other column).
A file that cannot be opened is a :class:`DataFileError`, never an ``OSError``,
so a bad row lands in ``skipped`` and the others are read.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..dtypes import describe_dtype, is_real
from ..errors import SDTError
from .csv_signal import read_csv_signal
from .recording import DataFileError, SignalTypeError
from .tokens import brief, quote

__all__ = ["ide_rate", "read_signal", "signal_shape"]

SUFFIXES = (".csv", ".npy", ".mat", ".ide")


def _orient(file: Path, shape: tuple[int, ...]) -> tuple[int, int]:
    if len(shape) == 1:
        return 1, shape[0]
    if len(shape) == 2:
        return (shape[1], shape[0]) if shape[0] > shape[1] else (shape[0], shape[1])
    raise DataFileError(f"{file}: array of shape {shape}; expected 1-D or 2-D")


def _mat_variable(file: Path, variable: str | None) -> tuple[str, tuple[int, ...]]:
    import scipy.io

    try:
        found = {name: shape for name, shape, _ in scipy.io.whosmat(file)}
    except OSError as exc:
        raise DataFileError(f"{file}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, NotImplementedError, TypeError) as exc:
        raise DataFileError(f"{file}: not a readable MATLAB file ({brief(exc)})") from None
    if variable is None:
        if len(found) != 1:
            raise DataFileError(
                f"{file}: holds variables {_names(sorted(found))}; name one in 'variable'"
            )
        variable = next(iter(found))
    if variable not in found:
        raise DataFileError(f"{file}: no variable {quote(variable)}; found {_names(sorted(found))}")
    return variable, found[variable]


def _names(names: list[str]) -> str:
    """At most 8 names, each a short token (names come from the file)."""
    return ", ".join(quote(n) for n in names[:8]) + (", ..." if len(names) > 8 else "")


def _load_npy(file: Path, **options: object) -> np.ndarray:
    try:
        data = np.load(file, allow_pickle=False, **options)  # type: ignore[call-overload]
    except OSError as exc:
        raise DataFileError(f"{file}: cannot read ({exc.strerror or brief(exc)})") from None
    except (ValueError, EOFError) as exc:
        raise DataFileError(f"{file}: not a readable NPY file ({brief(exc)})") from None
    return _real(file, data)


def _real(file: Path, data: np.ndarray) -> np.ndarray:
    """``data`` if it holds real numbers; booleans, complex, text... are refused by name."""
    if not is_real(data.dtype):
        raise SignalTypeError(
            f"{file}: holds {describe_dtype(data.dtype)}, not real numbers; save the signal "
            f"as int or float samples in g (nothing is converted for you)"
        )
    return data


def _ide(file: Path, variable: str | None):
    """One axis of an enDAQ IDE file (``variable = CHANNEL:AXIS``), on its even grid."""
    from .ide import read_variable  # idelib: on use only

    try:
        return read_variable(file, variable)
    except SDTError as exc:
        raise DataFileError(str(exc)) from None


def ide_rate(file: Path, variable: str | None) -> float:
    """The rate of an IDE row's signal, measured from its timestamps."""
    return _ide(file, variable).rate_hz


def signal_shape(file: Path, variable: str | None) -> tuple[tuple[int, int], str | None]:
    """((n_acquisitions, n_samples), note) of a signal file, reading as little as possible.

    ``note`` says which time column of a CSV is dropped (None otherwise). A
    CSV is parsed in full (its shape depends on its header and time column).
    """
    suffix = file.suffix.lower()
    if suffix == ".npy":
        return _orient(file, _load_npy(file, mmap_mode="r").shape), None
    if suffix == ".mat":
        return _orient(file, _mat_variable(file, variable)[1]), None
    if suffix == ".csv":
        parsed = read_csv_signal(file, variable)
        return parsed.data.shape, parsed.note  # type: ignore[return-value]
    if suffix == ".ide":
        read = _ide(file, variable)
        return (1, read.values.shape[1]), read.note
    raise DataFileError(f"{file}: unsupported file type {suffix!r}; use {', '.join(SUFFIXES)}")


def read_signal(file: Path, variable: str | None) -> np.ndarray:
    """The samples of a signal file as float64 (n_acquisitions, n_samples), all finite."""
    suffix = file.suffix.lower()
    if suffix == ".npy":
        data = _load_npy(file)
    elif suffix == ".mat":
        import scipy.io

        name, _ = _mat_variable(file, variable)
        try:
            data = scipy.io.loadmat(file, variable_names=[name])[name]
        except OSError as exc:
            raise DataFileError(f"{file}: cannot read ({exc.strerror or brief(exc)})") from None
        except (ValueError, NotImplementedError, TypeError) as exc:
            raise DataFileError(f"{file}: not a readable MATLAB file ({brief(exc)})") from None
    elif suffix == ".csv":
        return read_csv_signal(file, variable).data  # every value checked finite
    elif suffix == ".ide":
        return _finite(file, np.ascontiguousarray(_ide(file, variable).values), "sample", 0)
    else:
        raise DataFileError(f"{file}: unsupported file type {suffix!r}; use {', '.join(SUFFIXES)}")
    data = np.asarray(_real(file, np.asarray(data)), dtype=np.float64)
    _orient(file, data.shape)  # rejects 0-D and >2-D arrays
    if data.ndim == 2 and 1 in data.shape:
        data = data.reshape(-1)
    if data.ndim == 1:
        data = data[None, :]
    elif data.shape[0] > data.shape[1]:
        data = data.T
    return _finite(file, np.ascontiguousarray(data), "sample", 0)


def _finite(file: Path, data: np.ndarray, unit: str, offset: int) -> np.ndarray:
    bad = ~np.isfinite(data)
    if bad.any():
        acq, sample = np.argwhere(bad)[0]
        raise DataFileError(
            f"{file}: acquisition {acq}, {unit} {sample + offset}: "
            f"non-finite value {data[acq, sample]!r}"
        )
    return data
