"""A value in a message is a plain number, never NumPy's repr (issue 41, item 13).

NumPy 2 writes a scalar's repr as its constructor: on main a NaN read from a file was named
``non-finite value np.float64(nan)``, a rate read from a file ``got np.float64(-1.0)``. The
one helper (``sdt_framework.errors.shown``, re-exported by ``data/tokens``) is used wherever a
message quotes a value; these calls reach it from three layers with NumPy scalars.
"""

from __future__ import annotations

import numpy as np
import pytest

from sdt_framework.data.recording import DataFileError
from sdt_framework.edge.lora import symbol_time_s
from sdt_framework.errors import SDTError
from sdt_framework.features.windowing import cut_windows
from sdt_framework.signals.rules import finite
from sdt_framework.signals.tokens import shown


def test_shown_gives_the_python_number_of_a_numpy_scalar():
    assert [shown(v) for v in (np.float64("nan"), np.int64(5), np.float32(0.5), 0.1, "x")] == [
        "nan", "5", "0.5", "0.1", "'x'"
    ]  # fmt: skip


def test_a_samples_nan_is_named_as_nan(tmp_path):
    data = np.array([[0.0, np.inf, 1.0]])
    with pytest.raises(DataFileError) as caught:
        finite(tmp_path / "rec.npy", data)
    assert str(caught.value).endswith("acquisition 0, sample 1: non-finite value inf")


def test_a_rate_from_a_file_is_named_as_a_number():
    with pytest.raises(SDTError, match=r"got -1\.0$"):
        cut_windows(np.zeros(4096), np.float64(-1.0))


def test_an_api_argument_is_named_as_a_number_and_a_numpy_integer_is_an_integer():
    with pytest.raises(SDTError, match=r"integer 6\.\.12, got 13$"):
        symbol_time_s(np.int64(13), 125_000.0)
    assert symbol_time_s(np.int64(7), 125_000.0) == symbol_time_s(7, 125_000.0)
