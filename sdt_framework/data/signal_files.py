"""Read one signal file of a manifest row: CSV, NPY or MATLAB ``.mat``.

Every file becomes a float64 array (n_acquisitions, n_samples). A 1-D signal
is one acquisition. A 2-D array holds several acquisitions; its longer axis is
time (MATLAB users store signals as columns, numpy users as rows, and an
acquisition is always longer than the number of acquisitions). CSV: the named
column, or every column except ``time``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.csv as pacsv

from .recording import DataFileError

__all__ = ["read_signal", "signal_shape"]

SUFFIXES = (".csv", ".npy", ".mat")


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
    except (ValueError, OSError, NotImplementedError) as exc:
        raise DataFileError(f"{file}: not a readable MATLAB file ({exc})") from None
    if variable is None:
        if len(found) != 1:
            raise DataFileError(f"{file}: holds variables {sorted(found)}; name one in 'variable'")
        variable = next(iter(found))
    if variable not in found:
        raise DataFileError(f"{file}: no variable {variable!r}; found {sorted(found)}")
    return variable, found[variable]


def _csv_columns(file: Path, variable: str | None) -> np.ndarray:
    try:
        table = pacsv.read_csv(file, convert_options=pacsv.ConvertOptions(null_values=[""]))
    except pa.ArrowInvalid as exc:
        raise DataFileError(f"{file}: {exc}") from None
    names = [n for n in table.column_names if n.lower() != "time"]
    names = names if variable is None else [variable]
    if variable is not None and variable not in table.column_names:
        raise DataFileError(f"{file}: no column {variable!r}; found {table.column_names}")
    rows = []
    for name in names:
        column = table.column(name)
        if not pa.types.is_floating(column.type) and not pa.types.is_integer(column.type):
            values = column.to_pylist()
            for row, value in enumerate(values):
                try:
                    float(value)
                except (TypeError, ValueError):
                    raise DataFileError(
                        f"{file}: line {row + 2}, column {name!r}: {value!r} is not a number"
                    ) from None
        if column.null_count:
            row = int(np.flatnonzero(column.is_null().to_numpy(zero_copy_only=False))[0])
            raise DataFileError(f"{file}: line {row + 2}, column {name!r}: empty value")
        rows.append(np.asarray(column.to_numpy(zero_copy_only=False), dtype=np.float64))
    if not rows:
        raise DataFileError(f"{file}: no signal column")
    return np.vstack(rows)


def signal_shape(file: Path, variable: str | None) -> tuple[int, int]:
    """(n_acquisitions, n_samples) of a signal file, reading as little as possible."""
    suffix = file.suffix.lower()
    if suffix == ".npy":
        try:
            return _orient(file, np.load(file, mmap_mode="r", allow_pickle=False).shape)
        except ValueError as exc:
            raise DataFileError(f"{file}: not a readable NPY file ({exc})") from None
    if suffix == ".mat":
        return _orient(file, _mat_variable(file, variable)[1])
    if suffix == ".csv":
        return _csv_columns(file, variable).shape  # type: ignore[return-value]
    raise DataFileError(f"{file}: unsupported file type {suffix!r}; use {', '.join(SUFFIXES)}")


def read_signal(file: Path, variable: str | None) -> np.ndarray:
    """The samples of a signal file as float64 (n_acquisitions, n_samples), all finite."""
    suffix = file.suffix.lower()
    if suffix == ".npy":
        data = np.load(file, allow_pickle=False)
    elif suffix == ".mat":
        import scipy.io

        name, _ = _mat_variable(file, variable)
        data = scipy.io.loadmat(file, variable_names=[name])[name]
    elif suffix == ".csv":
        return _finite(file, _csv_columns(file, variable), "line", 2)
    else:
        raise DataFileError(f"{file}: unsupported file type {suffix!r}; use {', '.join(SUFFIXES)}")
    data = np.asarray(data, dtype=np.float64)
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
