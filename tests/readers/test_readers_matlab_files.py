"""MATLAB files as MATLAB and libmatio write them (issue 41, items 3, 4, 11, 13).

Item 3: MATLAB stores an empty array of a v7.3 file as a dataset holding its dimensions,
marked ``MATLAB_empty``; main listed ``x = zeros(10, 0)`` as a 2-sample signal [10, 0].
Item 4: a v5 file can hold one name twice (libmatio's v5 writer appended a variable it already
held; scipy.io.savemat writes what it is given); main read the first copy, where
``scipy.io.loadmat`` of the file keeps the last. Item 11: a v7.3 file whose data are all in
structs, cells or struct arrays gave "0 signals", exit 0. Item 13: a NaN in a file was named
``np.float64(nan)``. The v7.3 files are MATLAB's own (mat7.3's tests, in the corpus).
"""

from __future__ import annotations

from pathlib import Path

import h5py
import numpy as np
import pytest
import scipy.io

from sdt_framework.data.recording import DataFileError
from sdt_framework.signals.files import read_signal, scan_file

DATA = Path(__file__).parents[1] / "data" / "readers"
CORPUS = DATA / "corpus"


def test_v73_empty_arrays_are_listed_as_empty_not_as_their_dimensions(sdt_main, readers):
    file = CORPUS / "mat73-testfile15.mat"  # MATLAB: x_0 = [], x_10_0 = zeros(10, 0), ...
    with h5py.File(file) as handle:  # what main read as samples: the dimensions
        assert list(handle["x_10_0"][()]) == [10, 0] and handle["x_10_0"].attrs["MATLAB_empty"]
    infos = {i.variable: i for i in scan_file(file, readers)[1]}
    for name, size in [("x_0", "0 x 0"), ("x_0_10", "0 x 10"), ("x_10_0", "10 x 0")]:
        fault = f"{file}: variable '{name}' is an empty MATLAB double array ({size}): no samples"
        assert infos[name].fault == fault
        with pytest.raises(DataFileError) as caught:
            read_signal(file, readers, name)
        assert str(caught.value) == fault
    with h5py.File(file) as handle:  # a 10 x 1 column beside them reads as before
        np.testing.assert_array_equal(
            read_signal(file, readers, "x_10")[0], handle["x_10"][()][:, 0]
        )
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0
    assert "warning: listed, not read: " + infos["x_10_0"].fault in " ".join(err.split())


def _duplicated(file: Path) -> tuple[np.ndarray, np.ndarray]:
    """A v5 file holding 'acc' twice, zeros first, as a logger that wrote a placeholder and
    then the signal leaves it (scipy.io.savemat writes the items it is given, in order)."""
    signal = 0.5 * np.sin(2 * np.pi * 160.0 * np.arange(2048) / 25_600)
    zeros = np.zeros(2048)

    class Items:
        def items(self):
            return [("acc", zeros), ("acc", signal), ("rpm", np.array([1480.0]))]

    scipy.io.savemat(file, Items())
    return zeros, signal


def test_a_v5_name_stored_twice_reads_as_the_copy_scipy_keeps(sdt_main, tmp_path, readers):
    file = tmp_path / "run.mat"
    _, signal = _duplicated(file)
    assert [name for name, _, _ in scipy.io.whosmat(file)] == ["acc", "acc", "rpm"]
    infos = scan_file(file, readers)[1]
    assert [i.variable for i in infos] == ["acc", "rpm"]  # each name once
    assert infos[0].note == (
        f"{file}: variable 'acc' is stored 2 times (a writer that appends rather than "
        f"replaces); read as its last copy, the one scipy.io.loadmat keeps"
    )
    with pytest.warns(scipy.io.matlab.MatReadWarning, match="Duplicate variable name"):
        kept = scipy.io.loadmat(file)["acc"]
    np.testing.assert_array_equal(read_signal(file, readers, "acc"), kept)
    np.testing.assert_array_equal(read_signal(file, readers, "acc")[0], signal)
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 0 and "is stored 2 times" in err


def test_a_v73_file_of_struct_arrays_lists_each_numeric_field(sdt_main, readers):
    """MATLAB's raw1, a 5 x 1 struct array: impulse responses raw1(k).h (49 x 4), gains."""
    file = CORPUS / "mat73-testfile2.mat"
    code, out, err = sdt_main("dataset", "inspect", str(file), "--json")
    assert code == 0, err
    assert '"raw1(2).h"' in out
    infos = {i.variable: i for i in scan_file(file, readers)[1]}
    assert {f"raw1({k}).h" for k in range(1, 6)} <= set(infos)
    assert infos["raw1(2).h"].shape == (4, 49) and infos["raw1(2).h"].fault is None
    assert "is complex (double)" in str(infos["raw1(1).HSmooth"].fault)
    with h5py.File(file) as handle:  # element 2 of the field h: a reference into #refs#
        expected = handle[handle["raw1"]["h"][()].ravel()[1]][()]
    np.testing.assert_array_equal(read_signal(file, readers, "raw1(2).h"), expected)


def test_v73_struct_fields_and_cell_elements_read_by_their_matlab_names(readers):
    """mat7.3's testfile1.mat (MATLAB): data.struct_.test, data.cell_{1}; text is not listed
    inside a struct; a struct's NaN is refused naming it as a number (item 13)."""
    file = DATA / "testfile1.mat"
    infos = {i.variable: i for i in scan_file(file, readers)[1]}
    assert "data.arr_char" not in infos and "data.string_" not in infos
    with h5py.File(file) as handle:
        test = handle["data"]["struct_"]["test"][()]
        cell = handle[handle["data"]["cell_"][()].ravel()[0]][()]
    np.testing.assert_array_equal(
        read_signal(file, readers, "data.struct_.test"), test.reshape(1, -1)
    )
    np.testing.assert_array_equal(read_signal(file, readers, "data.cell_{1}"), cell.reshape(1, -1))
    with pytest.raises(DataFileError) as caught:
        read_signal(file, readers, "data.arr_nan")
    assert str(caught.value).endswith("acquisition 0, sample 0: non-finite value nan")


def test_a_v73_file_holding_no_numbers_says_what_it_holds(sdt_main, tmp_path):
    """A struct of text fields only (MATLAB's layout: a group of char datasets)."""
    file = tmp_path / "meta.mat"
    with h5py.File(file, "w", userblock_size=512) as handle:
        group = handle.create_group("meta")
        group.attrs["MATLAB_class"] = np.bytes_("struct")
        for name in ("operator", "site"):
            group.create_dataset(name, data=np.frombuffer(b"a\0b\0", dtype="<u2")[:, None])
            group[name].attrs["MATLAB_class"] = np.bytes_("char")
    with open(file, "r+b") as handle:
        handle.write(b"MATLAB 7.3 MAT-file, Platform: GLNXA64, HDF5 schema 1.00 .".ljust(116))
    code, _, err = sdt_main("dataset", "inspect", str(file))
    assert code == 2
    assert err.strip() == (
        f"error: {file}: variable 'meta' is a MATLAB struct that holds no numeric array "
        f"(fields 'operator', 'site')"
    )
