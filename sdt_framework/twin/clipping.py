"""Samples at full scale, on the device and on the twin: counted, not refused.

A device that clips on a shock still recorded everything below its range, and
the bands are judged anyway; how much clipped is reported beside them (count,
share of the compared samples, and which axes), so a reader weighs the bands
where the clipped peaks put their power. The twin clips where the modelled
part's range (``full_scale_g``) is smaller than the motion the reference saw.
A sample counts as clipped at 99.9 % of full scale or beyond.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

__all__ = ["AT_FULL_SCALE", "clipping", "describe"]

#: a sample at least this share of full scale counts as clipped
AT_FULL_SCALE = 0.999


def _side(values: np.ndarray, axes: Sequence[str], full: float) -> dict[str, Any]:
    per_axis = np.count_nonzero(np.abs(values) >= AT_FULL_SCALE * full, axis=1)
    return {
        "count": int(per_axis.sum()),
        "share": float(per_axis.sum() / values.size) if values.size else 0.0,
        "axes": {a: int(n) for a, n in zip(axes, per_axis, strict=True) if n},
    }


def clipping(device: np.ndarray, twin: np.ndarray, axes: Sequence[str],
             full_scale_g: float | None) -> dict[str, Any]:  # fmt: skip
    """Clipped samples of ``device`` and ``twin`` (rows: ``axes``) at ``full_scale_g``.

    ``device`` and ``twin`` keep their totals (ints) for scripts that read them;
    ``device_clipping`` and ``twin_clipping`` hold count, share and the axes.
    """
    full = full_scale_g or np.inf
    dev, twn = _side(device, axes, full), _side(twin, axes, full)
    return {
        "full_scale_g": full_scale_g,
        "device": dev["count"],
        "twin": twn["count"],
        "device_clipping": dev,
        "twin_clipping": twn,
    }


def describe(side: dict[str, Any]) -> str:
    """``0``, or ``1234 (0.81 % of samples; x 1200, z 34)``."""
    if not side["count"]:
        return "0"
    axes = ", ".join(f"{a} {n}" for a, n in side["axes"].items())
    return f"{side['count']} ({100 * side['share']:.2g} % of samples; {axes})"
