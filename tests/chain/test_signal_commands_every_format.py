"""``sdt degrade FILE`` and ``sdt features extract FILE`` on every registered format.

Each file is written by its format's own library (numpy, scipy.io, h5py behind MATLAB's
header, npTDMS, pyuff, scipy.io.wavfile; LVM in LabVIEW's layout, ``tests/reliability/
labview.py``) or is a real recording (enDAQ IDE), and read back here by that library alone.
The command's output must equal the Python API's ``degrade`` / ``extract`` of the library's
read, at the rate the library reads from the file (for NPY, CSV and MAT, which hold none: the
``--fs`` given). Issue 41 item 12, issue 42: before, both commands read only .npy/.csv
(``features extract`` only .npy) and always needed ``--fs``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from sdt_framework.api import degrade, extract
from sdt_framework.features import read_feature_table

from ..reliability.labview import lvm, segment

FS = 20000.0
G0 = 9.80665  # standard gravity, m/s^2 (ISO 80000-3): a TDMS channel is written in m/s^2
ENDAQ = Path(__file__).parents[1] / "data" / "endaq"
READERS = Path(__file__).parents[1] / "data" / "readers"
#: one real or library-written file per registered format
FORMATS = ["npy", "csv", "mat", "mat73", "tdms", "uff58", "lvm", "wav", "ide"]


def _acc(n: int = 40_000) -> np.ndarray:
    """2 s of a 50 Hz and a 730 Hz tone in g, with a little noise."""
    t = np.arange(n) / FS
    noise = np.random.default_rng(7).normal(0, 0.01, n)
    return 0.5 * np.sin(2 * np.pi * 50 * t) + 0.2 * np.sin(2 * np.pi * 730 * t) + noise


def _write(fmt: str, folder: Path) -> tuple[Path, list[str]]:
    """(the file, the options it needs); written by the format's own library."""
    x = _acc()
    file = folder / f"rec.{ {'mat73': 'mat', 'uff58': 'uff'}.get(fmt, fmt) }"
    if fmt == "npy":
        np.save(file, x)
    elif fmt == "csv":
        t = np.arange(x.size) / FS
        np.savetxt(file, np.c_[t, x], delimiter=",", header="time,acc", comments="", fmt="%.17g")
    elif fmt == "mat":
        import scipy.io

        scipy.io.savemat(file, {"acc": x[:, None]})  # MATLAB's column
    elif fmt == "mat73":
        import h5py

        with h5py.File(file, "w", userblock_size=512) as handle:
            handle.create_dataset("acc", data=x[None, :])  # MATLAB's column, column-major
            handle["acc"].attrs["MATLAB_class"] = np.bytes_("double")
        with open(file, "r+b") as handle:
            handle.write(b"MATLAB 7.3 MAT-file, Platform: GLNXA64, HDF5 schema 1.00 .".ljust(116))
    elif fmt == "tdms":
        from nptdms import ChannelObject, TdmsWriter

        props = {"wf_increment": 1.0 / FS, "unit_string": "m/s^2"}
        with TdmsWriter(file) as writer:
            writer.write_segment([
                ChannelObject("acc", "x", x * G0, properties=props),
                ChannelObject("acc", "y", -x * G0, properties=props),
            ])  # fmt: skip
        return file, ["--signal", "acc/x"]
    elif fmt == "uff58":
        import pyuff

        template = pyuff.UFF(str(READERS / "binary8byte.uff")).read_sets(0)  # a time history in g
        step = 1.0 / FS
        dataset = {**template, "data": x, "num_pts": x.size, "x": np.arange(x.size) * step,
                   "abscissa_inc": step, "id1": "acc"}  # fmt: skip
        pyuff.UFF(str(file)).write_sets(dataset, mode="add")  # a new file (binary, float64)
    elif fmt == "lvm":
        file.write_text(lvm([segment(["acc"], x[:, None], 1.0 / FS, "g")]))
    elif fmt == "wav":
        import scipy.io.wavfile

        counts = np.round(np.c_[x, -x] / 2.0 * 32767).astype(np.int16)  # full scale 2 g
        scipy.io.wavfile.write(file, int(FS), counts)
        return file, ["--signal", "ch1", "--full-scale-g", "2"]
    elif fmt == "ide":
        return ENDAQ / "SSX_Data.IDE", ["--signal", "8:x"]  # the 832M1 piezo at ~5 kHz
    return file, []


def _library_read(fmt: str, file: Path) -> tuple[np.ndarray, float | None]:
    """(samples in g, rate in Hz or None where the format holds none), by the library alone."""
    if fmt == "npy":
        return np.load(file), None
    if fmt == "csv":
        return np.loadtxt(file, delimiter=",", skiprows=1)[:, 1], None
    if fmt == "mat":
        import scipy.io

        return scipy.io.loadmat(file)["acc"][:, 0], None
    if fmt == "mat73":
        import h5py

        with h5py.File(file, "r") as handle:
            return handle["acc"][0], None
    if fmt == "tdms":
        from nptdms import TdmsFile

        channel = TdmsFile.read(file)["acc"]["x"]
        return channel[:] / G0, 1.0 / channel.properties["wf_increment"]
    if fmt == "uff58":
        import pyuff

        dataset = pyuff.UFF(str(file)).read_sets(0)
        return dataset["data"], 1.0 / dataset["abscissa_inc"]
    if fmt == "lvm":
        import lvm_read

        seg = lvm_read.read(str(file), read_from_pickle=False, dump_file=False)[0]
        return seg["data"][:, seg["Channel names"].index("acc")], 1.0 / seg["Delta_X"][0]
    if fmt == "wav":
        import scipy.io.wavfile

        rate, counts = scipy.io.wavfile.read(file)
        return counts[:, 0] / 32768.0 * 2.0, float(rate)
    from idelib.importer import openFile, readData

    with open(file, "rb") as handle:
        doc = openFile(handle, quiet=True)
        readData(doc)
        data = np.asarray(doc.channels[8].getSession().arraySlice(), dtype=np.float64)
        doc.close()
    times = data[0] * 1e-6  # microseconds
    slope = np.linalg.lstsq(np.c_[np.arange(times.size), np.ones(times.size)], times)[0][0]
    return data[1], 1.0 / slope  # the rate: a least-squares line through the timestamps


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, tuple[Path, list[str]]]:
    folder = tmp_path_factory.mktemp("formats")
    written = {}
    for fmt in FORMATS:
        (folder / fmt).mkdir()
        written[fmt] = _write(fmt, folder / fmt)
    return written


def _fs(rate: float | None) -> list[str]:
    return ["--fs", f"{FS:g}"] if rate is None else []


@pytest.mark.parametrize("fmt", FORMATS)
def test_degrade_reads_every_format_at_the_files_rate(fmt, files, sdt_main, tmp_path):
    file, options = files[fmt]
    expected_in, rate = _library_read(fmt, file)
    out = tmp_path / "y.npy"
    code, stdout, err = sdt_main("degrade", str(file), "--sensor", "adxl345", "--seed", "3",
                                 *options, *_fs(rate), "--out", str(out))  # fmt: skip
    assert code == 0, err
    fs = FS if rate is None else rate
    expected, fs_out = degrade(expected_in, fs, "adxl345", 3)
    y = np.load(out)
    assert y.shape == expected.shape and fs_out == 3200
    np.testing.assert_allclose(y, expected, rtol=0, atol=1e-12)
    # the summary says where the rate came from: the file's own field, or --fs
    assert f"at {fs:g} Hz ({'--fs' if rate is None else 'its '}" in stdout


@pytest.mark.parametrize("fmt", FORMATS)
def test_features_extract_reads_every_format_at_the_files_rate(fmt, files, sdt_main, tmp_path):
    file, options = files[fmt]
    signal, rate = _library_read(fmt, file)
    out = tmp_path / "f.parquet"
    code, stdout, err = sdt_main("features", "extract", str(file), *options, *_fs(rate),
                                 "--out", str(out))  # fmt: skip
    assert code == 0, err
    fs = FS if rate is None else rate
    assert f"at {fs:g} Hz ({'--fs' if rate is None else 'its '}" in stdout
    expected = extract(signal, fs, "paper8")
    table = read_feature_table(out)
    assert table.fs == pytest.approx(fs, rel=1e-12)
    assert table.values.shape == expected.values.shape and table.values.shape[0] >= 2
    np.testing.assert_allclose(table.values, expected.values, rtol=1e-6, atol=1e-9)
