"""Which array dtypes are signals: real numbers only, one rule for every reader.

A signal is acceleration in g (or raw counts): signed or unsigned integers or
floats. Booleans would become 0/1 g, complex numbers would lose their imaginary
part and objects or text cannot be samples, each without a word if converted
with ``astype(float)``; every reader (the Python API, the chain, the manifest
and ``sdt degrade``) asks :func:`is_real` and names what it found with
:func:`describe_dtype`.
"""

from __future__ import annotations

import numpy as np

__all__ = ["REAL_KINDS", "describe_dtype", "is_real"]

#: dtype kinds a signal may have: signed and unsigned integers, floats
REAL_KINDS = "iuf"
_KIND_NAMES = {
    "b": "booleans",
    "c": "complex numbers",
    "O": "Python objects",
    "U": "text",
    "S": "bytes",
    "M": "dates",
    "m": "time spans",
    "V": "records",
}


def is_real(dtype: np.dtype) -> bool:
    """Whether ``dtype`` holds real numbers (int or float)."""
    return dtype.kind in REAL_KINDS


def describe_dtype(dtype: np.dtype) -> str:
    """What a non-real dtype holds, in words: ``"booleans (dtype bool)"``."""
    return f"{_KIND_NAMES.get(dtype.kind, 'not real numbers')} (dtype {dtype})"
