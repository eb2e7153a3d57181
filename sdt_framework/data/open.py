"""Pick the dataset kind for a name or a path, and write any dataset in NLN-EMP layout.

``open_dataset`` is what the benchmark orchestrator and ``sdt dataset inspect``
call: a registered dataset name (``synthetic-pump``), an NLN-EMP root (a folder
holding ``Vibration/``) or a manifest (``.csv``/``.parquet``) all work.
``write_nln_emp`` turns recordings into the published CSV layout so that the
NLN-EMP reader handles generated and real data alike.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow as pa
import pyarrow.csv as pacsv

from ..errors import SDTError
from ..inputs import require_regular_file
from ..io import atomic_path
from .recording import Dataset, Recording

__all__ = ["load_dataset", "open_dataset", "round_significant", "write_nln_emp"]


def load_dataset(registry: Any, spec: Any, path: Any, **options: Any) -> Dataset:
    """The dataset ``spec`` (a ``DatasetSpec``) loads from ``path`` with ``options``; a loader
    that reads signal files (``reads_signal_files``: a manifest) is handed the readers of
    ``registry`` as ``readers=``, so that nothing below looks a registry up."""
    if spec.reads_signal_files and "readers" not in options:
        options = {**options, "readers": registry.signal_readers()}
    return spec.loader(path, **options)


def open_dataset(registry: Any, path_or_name: str | os.PathLike[str], **options: Any) -> Dataset:
    """Open a dataset by registered name or by path.

    Parameters
    ----------
    registry
        A :class:`sdt_framework.Registry` (datasets are plugins).
    path_or_name
        A registered dataset name; a folder with ``Vibration/`` (-> ``nln-emp``);
        a ``.csv``/``.parquet`` manifest (-> ``manifest``).
    **options
        Passed to the dataset's loader (e.g. ``seed=1``, ``motors=["Motor-4"]``).
    """
    text = str(path_or_name)
    names = {spec.name: spec for spec in registry.datasets()}
    if text in names and not Path(text).exists():
        spec = names[text]
        if spec.requires_path:
            raise SDTError(f"dataset {text!r} needs a path; give the folder or file instead")
        return load_dataset(registry, spec, None, **options)
    path = Path(text).expanduser()
    if path.is_dir():
        if (path / "Vibration").is_dir() or path.name == "Vibration":
            return load_dataset(registry, registry.dataset("nln-emp"), path, **options)
        raise SDTError(f"{path}: a folder without 'Vibration/'; expected an NLN-EMP root")
    if path.suffix.lower() in {".csv", ".parquet"}:
        require_regular_file(path, "manifest")
        if not path.is_file():
            raise SDTError(f"manifest {path} not found")
        return load_dataset(registry, registry.dataset("manifest"), path, **options)
    raise SDTError(
        f"{text!r} is neither a registered dataset ({', '.join(sorted(names)) or 'none'}) "
        f"nor an NLN-EMP folder nor a .csv/.parquet manifest"
    )


def round_significant(values: np.ndarray, digits: int = 6) -> np.ndarray:
    """Round to ``digits`` significant digits (vectorised ``'%.6g'``), zeros kept."""
    values = np.asarray(values, dtype=np.float64)
    magnitude = np.floor(np.log10(np.abs(np.where(values == 0, 1.0, values))))
    scale = 10.0 ** (digits - 1 - magnitude)
    return np.round(values * scale) / scale


def _write_csv(target: Path, data: np.ndarray, fs: float) -> None:
    n = data.shape[1]
    columns = {"time": np.arange(n) / fs}  # exact decimal multiples of 1/fs
    columns.update({str(i): round_significant(row) for i, row in enumerate(data)})
    header = ",".join(columns).encode() + b"\n"
    with atomic_path(target) as tmp, open(tmp, "wb") as handle:
        handle.write(header)
        pacsv.write_csv(
            pa.table(columns), handle, write_options=pacsv.WriteOptions(include_header=False)
        )


def write_nln_emp(dataset: Dataset, out: str | os.PathLike[str]) -> list[Path]:
    """Write every recording as ``Vibration/<machine>/<speed>/<run>/...-<ch>.csv``.

    A run named per speed folder (``"50/healthy 1"``: a machine at several speeds) is
    written under its speed folder as the directory it names (``healthy 1``).

    Values are rounded to 6 significant digits (relative error < 5e-7, far
    below any accelerometer's noise); the time column is exact. Each file is
    written atomically. Returns the written paths.
    """
    written = []
    for rec, data in dataset.iter_loaded():
        written.append(_target(Path(out), rec))
        _write_csv(written[-1], data, rec.sampling_rate_hz)
    return written


def _target(out: Path, rec: Recording) -> Path:
    """The file of ``rec``; a run named ``<speed>/<condition dir>`` (NLN-EMP read at several
    speeds) goes back to its condition directory under its speed folder."""
    speed = rec.speed or "0"
    run = rec.run.removeprefix(f"{speed}/")  # a run per speed folder is "<speed>/<dir>"
    name = f"Vibration_{rec.machine}_{speed}_time-{run}-{rec.channel}.csv"
    return out / "Vibration" / rec.machine / speed / run / name
