"""Argument checks of the public Python functions (``degrade``, ``extract``, ...).

They run once at the API boundary, so a wrong type fails with a
:class:`TypeError` naming the argument instead of being silently converted
(``int(1.5)``, ``int("3")``, ``float(True)``) or failing deep inside numpy.
Each error is also an :class:`~sdt_framework.errors.SDTError`, so the CLI
prints it as one line. Looking a registered name up is not done here: that is
:mod:`sdt_framework.api`, above the chain and the features.
"""

from __future__ import annotations

import math
import numbers
from typing import TypeVar

import numpy as np

from .dtypes import describe_dtype, is_real
from .errors import ArgumentTypeError, ArgumentValueError, one_line, shown
from .specs import Spec

__all__ = [
    "check_rate",
    "check_real",
    "check_seed",
    "check_spec",
    "describe_dtype",
    "real_array",
]

S = TypeVar("S", bound=Spec)


def _shown(value: object) -> str:
    return one_line(shown(value), 40)


def check_spec(kind: type[S], value: object, argument: str) -> S:
    """``value`` if it is a ``kind`` spec; a name is resolved one layer up, in :mod:`.api`.

    Raises
    ------
    ArgumentTypeError
        Anything else (also a :class:`TypeError`), naming ``argument`` and the accepted types.
    """
    if isinstance(value, kind):
        return value
    if isinstance(value, str):
        raise ArgumentTypeError(
            f"{argument} must be a {kind.__name__}; a registered name ({value!r}) is looked up "
            f"by sdt_framework.api (e.g. sdt_framework.api.degrade)"
        )
    raise ArgumentTypeError(
        f"{argument} must be a {kind.__name__} or the name of a registered {kind.kind} (str), "
        f"got {type(value).__name__}"
    )


def check_seed(seed: object, argument: str = "seed") -> int:
    """``seed`` as an int; bools, floats, strings and the like are refused, not converted."""
    if isinstance(seed, bool) or not isinstance(seed, numbers.Integral):
        raise ArgumentTypeError(
            f"{argument} must be an integer, got {type(seed).__name__} {_shown(seed)}"
        )
    return int(seed)


def check_real(value: object, argument: str, unit: str = "") -> float:
    """``value`` as a float if it is a real number (int, float, numpy scalar; not bool or str)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        what = f"a number of {unit}" if unit else "a number"
        raise ArgumentTypeError(
            f"{argument} must be {what} (int or float), got {type(value).__name__} {_shown(value)}"
        )
    return float(value)


def check_rate(fs: object, argument: str = "fs") -> float:
    """A sampling rate as a positive finite float, in Hz."""
    rate = check_real(fs, argument, "Hz")
    if not math.isfinite(rate) or rate <= 0:
        raise ArgumentValueError(f"{argument} must be a positive number of Hz, got {rate:g}")
    return rate


def real_array(x: object, argument: str = "x", label: str = "") -> np.ndarray:
    """``x`` as a numpy array of real numbers (int or float dtype), not copied if it is one.

    Booleans, complex numbers, Python objects and text are refused (a bool
    array would otherwise become 0/1 g without a word).
    """
    where = f" (recording {label!r})" if label else ""
    try:
        array = np.asarray(x)
    except (TypeError, ValueError) as exc:
        raise ArgumentValueError(
            f"{argument}{where} cannot be read as an array of numbers: {one_line(exc, 120)}"
        ) from None
    if not is_real(array.dtype):
        raise ArgumentTypeError(
            f"{argument}{where} must hold real numbers (int or float), got "
            f"{describe_dtype(array.dtype)}; convert it first, e.g. np.asarray({argument}, "
            f"dtype=float)"
        )
    return array
