"""The real-file corpus (tests/data/readers/corpus): every file read by sdt and by its format's
reference library, compared value by value, exactly.

Each file is fetched unchanged from a public repository (the README's table names the
repository, commit, path and licence of each; its licence file is beside it). For each
format, ``REFERENCES`` holds a function that reads one signal of a file with the format's
reference library (scipy.io.wavfile, scipy.io.loadmat, h5py, npTDMS, lvm_read, pyuff...),
knowing nothing of sdt's reader but the signal's name and the documented unit rule; the test
reads every signal sdt lists as readable with both and requires equal arrays. A file added to
the folder is tested once its format has a reference here, and must have a row in the README.
"""

from __future__ import annotations

import re
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import reader_for, scan_file

CORPUS = Path(__file__).parents[1] / "data" / "readers" / "corpus"
FILES = sorted(p for p in CORPUS.iterdir() if p.suffix.lower() not in (".md", ".txt"))
#: options a format's reader needs to read a file in g (integer WAV: 1 g at full scale)
OPTIONS: dict[str, dict[str, object]] = {"wav": {"full_scale_g": 1.0}}


def _wav(file: Path, variable: str) -> tuple[float | None, np.ndarray]:
    """scipy.io.wavfile (no memory map): integer samples are counts left-justified in their
    container, so 1 g full scale is count / 2**(container bits - 1); 8-bit is unsigned."""
    import scipy.io.wavfile

    with warnings.catch_warnings():  # a PEAK or bext chunk is skipped, as it should be
        warnings.simplefilter("ignore", scipy.io.wavfile.WavFileWarning)
        rate, data = scipy.io.wavfile.read(file)
    column = (data if data.ndim == 2 else data[:, None])[:, int(variable[2:]) - 1]
    if column.dtype.kind == "u":
        return rate, (column.astype(np.float64) - 128.0) / 128.0
    if column.dtype.kind == "i":
        return rate, column.astype(np.float64) / 2.0 ** (8 * column.dtype.itemsize - 1)
    return rate, column.astype(np.float64)


def _mat(file: Path, variable: str) -> tuple[float | None, np.ndarray]:
    """scipy.io.loadmat of the whole file (a name stored twice: the copy loadmat keeps)."""
    import scipy.io

    return None, scipy.io.loadmat(file)[variable]


def _mat73(file: Path, variable: str) -> tuple[float | None, np.ndarray]:
    """h5py, following the MATLAB expression: ``.f`` a struct's member, ``{k}`` the k-th
    reference of a cell, ``(k).f`` the k-th reference of a struct array's field."""
    import h5py

    parts = re.findall(r"^[^.{}()]+|\.[^.{}()]+|\{\d+\}|\(\d+\)\.[^.{}()]+", variable)
    assert "".join(parts) == variable
    with h5py.File(file, "r") as handle:
        node = handle[parts[0]]
        for part in parts[1:]:
            if part.startswith("."):
                node = node[part[1:]]
            elif part.startswith("{"):
                node = handle[node[()].ravel()[int(part[1:-1]) - 1]]
            else:
                k, field = part[1:].split(").")
                node = handle[node[field][()].ravel()[int(k) - 1]]
        return None, node[()]


def _lvm(file: Path, variable: str) -> tuple[float | None, np.ndarray]:
    """lvm_read: the channel's column in each segment (one a row), at 1 / its Delta_X cell (cell
    c - 1 of data column c where the file has X columns, cell c where it has none); a column
    empty below its Samples holds those Samples (a channel shorter than the others)."""
    import lvm_read

    lvm = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)
    offset = 0 if lvm["X_Columns"] == "No" else 1
    rows, rates = [], set()
    for s in range(lvm["Segments"]):
        column = lvm[s]["Channel names"].index(variable)
        values = lvm[s]["data"][:, column]
        samples = lvm[s]["Samples"][column - offset]
        if np.isfinite(samples) and np.isnan(values[int(samples) :]).all():
            values = values[: int(samples)]
        rows.append(values)
        rates.add(1 / lvm[s]["Delta_X"][column - offset])
    (rate,) = rates
    return rate, np.stack(rows)


def _uff58(file: Path, variable: str) -> tuple[float | None, np.ndarray]:
    """pyuff: dataset 58 number ``variable`` (counting the file's datasets 58 from 1), at
    1 / its abscissa increment."""
    import pyuff

    uff = pyuff.UFF(str(file))
    index = [i for i, kind in enumerate(uff.get_set_types()) if kind == 58][int(variable) - 1]
    dataset = uff.read_sets(index)
    return 1 / dataset["abscissa_inc"], dataset["data"]


def _tdms(file: Path, variable: str) -> tuple[float | None, np.ndarray]:
    """npTDMS: the channel whose group and channel names joined by '/' are ``variable`` (either
    may hold '/'), scaled, at 1 / its wf_increment."""
    from nptdms import TdmsFile

    tdms = TdmsFile.read(file)
    (channel,) = [
        c for g in tdms.groups() for c in g.channels() if f"{g.name}/{c.name}" == variable
    ]
    increment = channel.properties.get("wf_increment")
    return (None if increment is None else 1 / increment), channel[:]


#: reader name -> (file, variable) -> (the rate the library reads, or None; the samples)
REFERENCES: dict[str, Callable[[Path, str], tuple[float | None, np.ndarray]]] = {
    "wav": _wav,
    "mat": _mat,
    "mat73": _mat73,
    "lvm": _lvm,
    "uff58": _uff58,
    "tdms": _tdms,
}


def _as_acquisitions(data: np.ndarray) -> np.ndarray:
    """The documented orientation: 1-D is one acquisition, a 2-D array's longer axis is time."""
    data = np.asarray(data, dtype=np.float64)
    if data.ndim == 1 or 1 in data.shape:
        return data.reshape(1, -1)
    return data.T if data.shape[0] > data.shape[1] else data


@pytest.mark.parametrize("file", FILES, ids=[f.name for f in FILES])
def test_every_signal_equals_its_reference_library(registry, file):
    readers = registry.signal_readers()
    reader = reader_for(file, readers)
    assert reader.name in REFERENCES, f"no reference library for {reader.name} in this test"
    options = OPTIONS.get(reader.name, {})
    _, infos = scan_file(file, readers, **options)
    readable = [info for info in infos if info.fault is None]
    assert readable, f"{file.name}: sdt lists no readable signal"
    for info in readable:
        rate, expected = REFERENCES[reader.name](file, str(info.variable))
        expected = _as_acquisitions(expected)
        assert info.shape == expected.shape and info.rate_hz == rate
        if not np.isfinite(expected).all():  # refused, naming the first such value as a number
            first = expected[~np.isfinite(expected)][0]
            with pytest.raises(DataFileError, match=f"non-finite value {first}$"):
                reader.read(file, info.variable, **options)
            continue
        got = reader.read(file, info.variable, **options)
        np.testing.assert_array_equal(got, expected, err_msg=info.variable)


def _readme_rows() -> list[str]:
    text = (CORPUS / "README.md").read_text(encoding="utf-8")
    return [line for line in text.splitlines() if line.startswith("| `")]


def test_every_file_has_a_readme_row_and_its_licence_is_beside_it():
    rows = _readme_rows()
    named = {name for row in rows for name in re.findall(r"`([^`]+)`", row.split("|")[1])}
    assert {f.name for f in FILES} <= named
    for licence in {name for row in rows for name in re.findall(r"LICENSE-[\w.-]+\.txt", row)}:
        assert (CORPUS / licence).is_file(), licence
    assert sum(f.stat().st_size for f in CORPUS.iterdir()) < 8_000_000  # a few MB in all
