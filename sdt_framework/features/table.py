"""The feature table: float32 values with their names, units and window provenance.

Units travel with the values in every format:

- in memory, :class:`FeatureTable` holds ``names`` and ``units``;
- in Parquet, each feature column carries ``unit`` field metadata and the
  schema metadata holds the feature set, rate, window and settling lengths;
- in CSV, a feature column is headed ``name[unit]`` (e.g. ``V_RMS[mm/s]``;
  dimensionless features use ``[1]``), so the file stays one header row plus
  numeric rows that any CSV reader loads as numbers.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from ..csv_cells import escape_frame, unescape_frame
from ..errors import SDTError
from ..io import atomic_path

__all__ = ["FeatureTable", "read_feature_table", "write_feature_table"]

_INDEX = ("acquisition", "window")
_CSV_HEADER = re.compile(r"^(?P<name>.+)\[(?P<unit>[^\[\]]*)\]$")
_META = "sdt_framework.features"


@dataclass(frozen=True)
class FeatureTable:
    """Features of every window, one row per window.

    Attributes
    ----------
    values
        float32, shape (n_windows, n_features).
    names, units
        Feature names and their units, in column order.
    acquisition, window
        int64, shape (n_windows,): input row and window index within it.
    feature_set
        Name of the feature set that produced the values (``"paper8+env_bpfo"``).
    fs
        Sampling rate of the signal, Hz.
    window_length, settle
        Samples per window and settling samples discarded per acquisition.
    speed
        For a set in orders of the running speed: the speed it was computed at and
        where it comes from (``"1480 rpm (24.67 Hz; given: ...)"``, or an estimate
        read off the spectrum, named so); empty for any other set.
    """

    values: np.ndarray
    names: tuple[str, ...]
    units: tuple[str, ...]
    acquisition: np.ndarray
    window: np.ndarray
    feature_set: str
    fs: float
    window_length: int
    settle: int
    speed: str = ""

    @property
    def bytes_per_window(self) -> int:
        """Size of one window's feature vector as stored (float32: 4 B per feature)."""
        return int(self.values.dtype.itemsize * self.values.shape[1])

    def to_frame(self) -> pd.DataFrame:
        """A DataFrame with columns acquisition, window, then one per feature.

        Units are kept in ``frame.attrs["units"]`` (feature name -> unit).
        """
        frame = pd.DataFrame(self.values, columns=list(self.names))
        frame.insert(0, "window", self.window)
        frame.insert(0, "acquisition", self.acquisition)
        frame.attrs["units"] = dict(zip(self.names, self.units, strict=True))
        frame.attrs["feature_set"] = self.feature_set
        if self.speed:
            frame.attrs["speed"] = self.speed
        return frame

    def metadata(self) -> dict[str, object]:
        """What a file needs besides the columns to rebuild this table."""
        meta: dict[str, object] = {
            "feature_set": self.feature_set,
            "fs": self.fs,
            "window_length": self.window_length,
            "settle": self.settle,
            "units": dict(zip(self.names, self.units, strict=True)),
        }
        if self.speed:  # only a set in orders of the running speed has one
            meta["speed"] = self.speed
        return meta


def write_feature_table(table: FeatureTable, path: str | os.PathLike[str]) -> Path:
    """Write ``table`` atomically to ``.csv`` or ``.parquet``, units included."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in {".csv", ".parquet"}:
        raise SDTError(f"{path}: output must end in .csv or .parquet, not {suffix or '(none)'!r}")
    frame = table.to_frame()
    with atomic_path(path) as tmp:
        if suffix == ".csv":
            frame.columns = [
                *_INDEX,
                *(f"{n}[{u}]" for n, u in zip(table.names, table.units, strict=True)),
            ]
            escape_frame(frame).to_csv(tmp, index=False, float_format="%.9g")
        else:
            import pyarrow as pa
            import pyarrow.parquet as pq

            arrow = pa.Table.from_pandas(frame, preserve_index=False)
            fields = [
                f.with_metadata({"unit": table.units[table.names.index(f.name)]})
                if f.name in table.names
                else f
                for f in arrow.schema
            ]
            schema = pa.schema(fields, metadata={_META: json.dumps(table.metadata())})
            pq.write_table(arrow.cast(schema), tmp)
    return path


def read_feature_table(path: str | os.PathLike[str]) -> FeatureTable:
    """Read a table written by :func:`write_feature_table` (CSV or Parquet)."""
    path = Path(path)
    if path.suffix.lower() == ".parquet":
        import pyarrow.parquet as pq

        arrow = pq.read_table(path)
        meta = json.loads((arrow.schema.metadata or {}).get(_META.encode(), b"{}"))
        frame = arrow.to_pandas()
        names = tuple(c for c in frame.columns if c not in _INDEX)
        units = tuple(arrow.schema.field(n).metadata[b"unit"].decode() for n in names)
    else:
        frame = unescape_frame(pd.read_csv(path))
        meta = {}
        parsed = [_CSV_HEADER.match(c) for c in frame.columns if c not in _INDEX]
        if not all(parsed):
            raise SDTError(f"{path}: feature columns must be headed 'name[unit]'")
        names = tuple(m["name"] for m in parsed)  # type: ignore[index]
        units = tuple(m["unit"] for m in parsed)  # type: ignore[index]
    values = frame.drop(columns=list(_INDEX)).to_numpy(dtype=np.float32)
    return FeatureTable(
        values=values,
        names=names,
        units=units,
        acquisition=frame["acquisition"].to_numpy(dtype=np.int64),
        window=frame["window"].to_numpy(dtype=np.int64),
        feature_set=str(meta.get("feature_set", "")),
        fs=float(meta.get("fs", float("nan"))),
        window_length=int(meta.get("window_length", -1)),
        settle=int(meta.get("settle", -1)),
        speed=str(meta.get("speed", "")),
    )
