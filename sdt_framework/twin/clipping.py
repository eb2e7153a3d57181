"""Samples at full scale, on the device and on the twin: counted, not refused.

A device that clips on a shock still recorded everything below its range, and
the bands are judged anyway; how much clipped is reported beside them (count,
share of the compared samples, and which axes), so a reader weighs the bands
where the clipped peaks put their power. The twin clips where the modelled
part's range (``full_scale_g``) is smaller than the motion the reference saw.
A sample counts as clipped at 99.9 % of full scale or beyond.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

__all__ = ["AT_FULL_SCALE", "ClippedSide", "Clipping", "clipping", "describe"]

#: a sample at least this share of full scale counts as clipped
AT_FULL_SCALE = 0.999


@dataclass(frozen=True)
class ClippedSide:
    """One side's samples at full scale: how many, their share of the compared samples,
    and how many on each axis that has any."""

    count: int
    share: float
    axes: Mapping[str, int]


@dataclass(frozen=True)
class Clipping:
    """Both sides' samples at full scale (``full_scale_g``: the part's range, None when the
    profile gives none); ``device`` and ``twin`` keep the totals for scripts that read them."""

    full_scale_g: float | None
    device: int
    twin: int
    device_clipping: ClippedSide
    twin_clipping: ClippedSide


def _side(values: np.ndarray, axes: Sequence[str], full: float) -> ClippedSide:
    per_axis = np.count_nonzero(np.abs(values) >= AT_FULL_SCALE * full, axis=1)
    return ClippedSide(
        count=int(per_axis.sum()),
        share=float(per_axis.sum() / values.size) if values.size else 0.0,
        axes={a: int(n) for a, n in zip(axes, per_axis, strict=True) if n},
    )


def clipping(device: np.ndarray, twin: np.ndarray, axes: Sequence[str],
             full_scale_g: float | None) -> Clipping:  # fmt: skip
    """Clipped samples of ``device`` and ``twin`` (rows: ``axes``) at ``full_scale_g``."""
    full = full_scale_g or np.inf
    dev, twn = _side(device, axes, full), _side(twin, axes, full)
    return Clipping(full_scale_g, dev.count, twn.count, dev, twn)


def describe(side: ClippedSide) -> str:
    """``0``, or ``1234 (0.81 % of samples; x 1200, z 34)``."""
    if not side.count:
        return "0"
    axes = ", ".join(f"{a} {n}" for a, n in side.axes.items())
    return f"{side.count} ({100 * side.share:.2g} % of samples; {axes})"
