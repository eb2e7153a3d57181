"""Compose feature sets by name: ``"paper8+env_bpfo"`` is paper8's columns then env_bpfo's.

A composed set is resolved on demand from registered parts and never
registered itself (its ``+`` name is reserved for composition). Its compute
hands the same centred windows to each part (and the recording's context to a
part working in orders of the running speed), checks each part's output (so an
error names the part that misbehaved) and concatenates the columns. It needs
the speed when a part does; its order bands are its parts', and a node computes
the FFTs of every part (their sum: an upper bound, as two parts may share one).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, Protocol

import numpy as np
from pydantic import Field, field_validator

from ..errors import SDTError
from ..specs import _NAME, FeatureContext, FeatureSetSpec, OrderBand
from .checks import check_feature_output

__all__ = ["ComposedFeatureSetSpec", "compose", "resolve_feature_set"]

SEPARATOR = "+"


class FeatureSetLookup(Protocol):
    """Where registered feature sets are looked up by name (a :class:`~sdt_framework.Registry`)."""

    def feature_set(self, name: str) -> FeatureSetSpec:
        """The feature set called ``name``."""
        ...


class ComposedFeatureSetSpec(FeatureSetSpec):
    """A feature set made of other feature sets, columns in part order."""

    parts: tuple[FeatureSetSpec, ...] = Field(min_length=2, description="The composed sets.")

    @field_validator("name")
    @classmethod
    def _check_name(cls, value: str) -> str:
        pieces = value.split(SEPARATOR)
        if len(pieces) < 2 or not all(_NAME.match(p) for p in pieces):
            raise ValueError(f"{value!r} is not a composed name such as 'paper8+env_bpfo'")
        return value

    @property
    def bytes_per_window(self) -> int:
        """Edge payload of one window of one axis: the sum over the parts."""
        return sum(part.bytes_per_window for part in self.parts)

    @property
    def value_dtypes(self) -> tuple[str, ...]:
        """The on-node type of each feature: each part's, in column order."""
        return tuple(d for part in self.parts for d in part.value_dtypes)

    def with_dtype(self, dtype: str) -> FeatureSetSpec:
        """A copy whose parts all send their values as ``dtype``."""
        parts = tuple(part.with_dtype(dtype) for part in self.parts)
        return self.model_validate(
            {**dict(self), "parts": parts, "dtype": dtype, "bytes_per_value": None}
        )

    def content_dict(self) -> dict[str, Any]:
        """The parts' behaviour-defining fields, for cache keys."""
        data = super().content_dict()
        data["parts"] = [part.content_dict() for part in self.parts]
        return data


def compose(parts: Sequence[FeatureSetSpec]) -> FeatureSetSpec:
    """One feature set computing every part's features, columns concatenated.

    Parameters
    ----------
    parts
        Feature sets in column order; one part is returned unchanged.

    Raises
    ------
    SDTError
        No parts, or a feature name present in two parts (both are named).
    """
    parts = tuple(parts)
    if not parts:
        raise SDTError("compose needs at least one feature set")
    if len(parts) == 1:
        return parts[0]
    owner: dict[str, str] = {}
    for part in parts:
        for feature_name in part.feature_names:
            if feature_name in owner:
                raise SDTError(
                    f"feature {feature_name!r} is provided by both {owner[feature_name]!r} and "
                    f"{part.name!r}; compose sets whose feature names differ"
                )
            owner[feature_name] = part.name
    name = SEPARATOR.join(part.name for part in parts)

    def compute(
        windows: np.ndarray, fs: float, context: FeatureContext | None = None
    ) -> np.ndarray:
        n_windows = windows.shape[0]
        return np.concatenate(
            [
                check_feature_output(
                    p.compute(windows, fs, context) if p.needs_speed else p.compute(windows, fs),
                    n_windows,
                    p,
                )
                for p in parts
            ],
            axis=1,
        )

    def order_bands(context: FeatureContext) -> tuple[OrderBand, ...]:
        return tuple(b for p in parts if p.order_bands is not None for b in p.order_bands(context))

    compute.__qualname__ = f"compose[{name}]"
    order_bands.__qualname__ = f"compose[{name}].order_bands"
    needs_speed = any(p.needs_speed for p in parts)
    return ComposedFeatureSetSpec(
        name=name,
        description="Composed: "
        + "; ".join(f"{p.name} ({', '.join(p.feature_names)})" for p in parts),
        source=", ".join(p.source for p in parts if p.source),
        feature_names=tuple(f for p in parts for f in p.feature_names),
        units=tuple(u for p in parts for u in p.units),
        compute=compute,
        parts=parts,
        bands=tuple(band for p in parts for band in p.bands),
        needs_speed=needs_speed,
        order_bands=order_bands if any(p.order_bands is not None for p in parts) else None,
        node_ffts=sum(p.node_ffts for p in parts),
        node_speed_pad=max(p.node_speed_pad for p in parts),  # one speed estimate serves all
    )


def resolve_feature_set(registry: FeatureSetLookup, name: str) -> FeatureSetSpec:
    """The feature set called ``name``, composing ``"a+b+c"`` from registered parts.

    Parameters
    ----------
    registry
        Where the parts are registered.
    name
        A registered name (``"paper8"``) or names joined by ``+``
        (``"paper8+env_bpfo"``); spaces around ``+`` are ignored.

    Raises
    ------
    SDTError
        An empty part, an unknown part (with the closest registered name), or
        duplicate feature names across parts.
    """
    pieces = [piece.strip() for piece in name.split(SEPARATOR)]
    if not all(pieces):
        raise SDTError(f"feature set {name!r} has an empty part; write e.g. 'paper8+env_bpfo'")
    return compose([registry.feature_set(piece) for piece in pieces])
