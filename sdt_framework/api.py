"""The public Python functions that also take a registered name.

``degrade(x, fs, "adxl345")`` and ``extract(y, fs, "paper8")`` take a spec or a
registered name (for a sensor also a part in a mode, ``"adxl355[range=8g]"``;
for a feature set a composition, ``"paper8+env_bpfo"``). A name is looked up in
:func:`sdt_framework.registry.default_registry`, built on first use. This
module sits above :mod:`sdt_framework.chain` and :mod:`sdt_framework.features`,
which take resolved specs and never import the registry; given specs, the
functions here are exactly theirs.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import registry as _registry
from .errors import ArgumentTypeError
from .features import FeatureTable, resolve_feature_set
from .features import extract as _extract
from .features.windowing import SETTLE_S, WINDOW_S
from .specs import FeatureContext, FeatureSetSpec, SensorSpec, Spec

__all__ = ["degrade", "extract", "resolve"]

S = TypeVar("S", bound=Spec)


def resolve(kind: type[S], value: object, argument: str) -> S:
    """``value`` itself if it is a ``kind`` spec, the registered one if it is a name.

    A sensor profile built in Python that lists stages no registry bound is
    bound in the default registry (the chain below never looks a registry up).

    A sensor name may be a catalogue part in a mode, ``"adxl355[range=8g]"``,
    resolved as ``sdt degrade --sensor`` resolves it; a feature-set name may
    compose registered sets, ``"paper8+env_bpfo"``.

    Raises
    ------
    ArgumentTypeError
        Anything else (also a :class:`TypeError`), naming ``argument`` and the accepted types.
    UnknownNameError
        A name nothing registers (with the closest match).
    """
    if isinstance(value, SensorSpec) and issubclass(kind, SensorSpec):
        if any(use.spec is None for use in value.stages):  # built in Python: bind its stages
            return _registry.default_registry().bind(value)  # type: ignore[return-value]
        return value  # type: ignore[return-value]
    if isinstance(value, kind):
        return value
    if isinstance(value, str):
        registry = _registry.default_registry()
        if issubclass(kind, SensorSpec):  # a part in a mode too, as the CLI takes it
            return registry.sensor(value)  # type: ignore[return-value]
        if issubclass(kind, FeatureSetSpec):
            return resolve_feature_set(registry, value)  # type: ignore[return-value]
        return registry._get(kind, value)
    example = " (str, e.g. 'paper8')" if issubclass(kind, FeatureSetSpec) else " (str)"
    raise ArgumentTypeError(
        f"{argument} must be a {kind.__name__} or the name of a registered {kind.kind}"
        f"{example}, got {type(value).__name__}"
    )


def degrade(
    x: ArrayLike,
    fs: float,
    sensor: SensorSpec | str,
    seed: int = 0,
    *,
    noise: bool = True,
    label: str = "",
    first_index: int = 0,
    acquisition_ids: Sequence[int | str] | None = None,
    threads: int | None = None,
    other_axes: Mapping[str, ArrayLike] | None = None,
) -> tuple[NDArray[np.float64], float]:
    """:func:`sdt_framework.chain.degrade`, ``sensor`` also a registered name (``"adxl345"``)."""
    from .chain import degrade as _degrade  # scipy: imported on use

    return _degrade(
        x,
        fs,
        resolve(SensorSpec, sensor, "sensor"),
        seed,
        noise=noise,
        label=label,
        first_index=first_index,
        acquisition_ids=acquisition_ids,
        threads=threads,
        other_axes=other_axes,
    )


def extract(
    x: np.ndarray,
    fs: float,
    feature_set: FeatureSetSpec | str,
    *,
    window_s: float = WINDOW_S,
    settle_s: float = SETTLE_S,
    label: str = "",
    context: FeatureContext | None = None,
) -> FeatureTable:
    """:func:`sdt_framework.features.extract`, ``feature_set`` also a name (``"paper8"``);
    ``context`` the recording's speed for a set in orders (``"orders"``)."""
    spec = resolve(FeatureSetSpec, feature_set, "feature_set")
    return _extract(x, fs, spec, window_s=window_s, settle_s=settle_s, label=label, context=context)
