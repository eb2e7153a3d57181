"""User-written features in a few lines: the ``@feature`` decorator.

A user feature is a function ``(windows, fs) -> values`` returning one value per
window. The decorator wraps it into a one-feature :class:`FeatureSetSpec`, the
same kind of object the built-in ``paper8`` registers, so it goes through the
same registry, hook and checks::

    @feature(name="env_bpfo", unit="g")
    def env_bpfo(windows, fs):
        ...

    registry.add(env_bpfo.spec)          # in a notebook or script

    @hookimpl                            # or in a plugin module
    def register_features(register):
        register(env_bpfo.spec)

The function stays callable as before; windows reach it mean-centred (float64,
shape (n_windows, n_samples)) when called through :func:`extract`.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any, Protocol

import numpy as np

from ..errors import SDTError
from ..specs import FeatureSetSpec

__all__ = ["Feature", "feature"]

FeatureFunction = Callable[[np.ndarray, float], Any]


class SpecSink(Protocol):
    """Where a decorated feature registers itself (a :class:`~sdt_framework.Registry`)."""

    def add(self, spec: FeatureSetSpec) -> object:
        """Register ``spec``."""


class Feature:
    """A decorated feature function together with its one-feature spec.

    Calling it calls the original function. ``spec`` is the
    :class:`FeatureSetSpec` to register.
    """

    def __init__(self, function: FeatureFunction, spec: FeatureSetSpec) -> None:
        functools.update_wrapper(self, function)
        self.function = function
        self.spec = spec

    def __call__(self, windows: np.ndarray, fs: float) -> Any:
        return self.function(windows, fs)

    def __repr__(self) -> str:
        return f"<feature {self.spec.name!r} [{self.spec.units[0]}]>"


def _column(function: FeatureFunction, name: str) -> Callable[[np.ndarray, float], np.ndarray]:
    """Wrap a per-window function as a (n_windows, 1) compute, checking its shape."""

    @functools.wraps(function)
    def compute(windows: np.ndarray, fs: float) -> np.ndarray:
        values = np.asarray(function(windows, fs))
        n_windows = windows.shape[0]
        if values.shape not in {(n_windows,), (n_windows, 1)}:
            raise SDTError(
                f"feature {name!r} ({function.__module__}.{function.__qualname__}) returned shape "
                f"{values.shape} for {n_windows} windows; expected ({n_windows},), one value "
                f"per window"
            )
        return values.reshape(n_windows, 1)

    return compute


def feature(
    name: str,
    unit: str,
    *,
    description: str = "",
    source: str = "",
    bytes_per_value: int | None = None,
    dtype: str | None = None,
    registry: SpecSink | None = None,
) -> Callable[[FeatureFunction], Feature]:
    """Turn ``function(windows, fs) -> (n_windows,)`` into a registrable feature.

    Parameters
    ----------
    name
        Feature (and feature set) name, lower-case, e.g. ``"env_bpfo"``.
    unit
        Unit of the value, e.g. ``"g"``; ``"1"`` for dimensionless.
    description, source
        One line saying what it is, and where it comes from.
    bytes_per_value, dtype
        How the node sends the value: dtype "float32" (4 bytes, the default)
        or "float16" (2 bytes); either one is enough.
    registry
        If given, register the feature there at once (in-process).

    Returns
    -------
    Callable
        A decorator returning a :class:`Feature` (callable, with ``.spec``).
    """

    def decorate(function: FeatureFunction) -> Feature:
        doc = (function.__doc__ or "").strip().splitlines()
        spec = FeatureSetSpec(
            name=name,
            description=description or (doc[0] if doc else ""),
            source=source,
            feature_names=(name,),
            units=(unit,),
            compute=_column(function, name),
            bytes_per_value=bytes_per_value,
            dtype=dtype,
        )
        wrapped = Feature(function, spec)
        if registry is not None:
            registry.add(spec)
        return wrapped

    return decorate
