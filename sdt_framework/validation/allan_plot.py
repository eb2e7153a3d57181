"""The Allan panel of ``sdt validate-noise --plot``: curves, -1/2 lines, read-off points.

Draws on an axes it is given (no matplotlib import), like
:func:`sdt_framework.chain.noise_plot.draw_noise`.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .allan import AllanCurve
from .allan_check import AllanCheck

__all__ = ["draw_allan"]


def _curve(ax: Any, curve: AllanCurve, colour: str) -> None:
    if not len(curve.taus):
        return
    ax.loglog(curve.taus, curve.adev * 1e6, "o-", ms=2.5, lw=0.8, color=colour, label=curve.label)
    if math.isfinite(curve.n_g):  # the -1/2 line, out to tau = 1 s where N is read
        t = np.geomspace(min(curve.taus[0], 1.0), max(curve.taus[-1], 1.0), 50)
        ax.loglog(t, curve.n_g * 1e6 / np.sqrt(t), "--", lw=0.8, color=colour)
        ax.plot(
            [1.0],
            [curve.n_g * 1e6],
            "s",
            ms=6,
            mfc="none",
            color=colour,
            label=f"N = {curve.n_g * 1e6:.1f} µg/√Hz (at 1 s)",
        )
    if math.isfinite(curve.floor_g):
        ax.plot(
            [curve.floor_tau],
            [curve.floor_g * 1e6],
            "D",
            ms=6,
            mfc="none",
            color=colour,
            label=f"B = {curve.b_g * 1e6:.1f} µg (floor / 0.664)",
        )


def draw_allan(ax: Any, allan: AllanCheck, colours: tuple[str, str] = ("0.5", "C0")) -> None:
    """Log-log overlapping ADEV (µg) vs tau (s) of the recording (if any) and the SDT output.

    Each curve gets its -1/2 line through N (dashed, extended to tau = 1 s) and
    its read-off points: N at 1 s (square) and the bias-instability floor
    (diamond); the configured N is the dotted black line.
    """
    if allan.recording is not None:
        _curve(ax, allan.recording, colours[0])
    _curve(ax, allan.sdt, colours[1])
    n_cfg = allan.configured.n_g
    if n_cfg is not None:
        lo, hi = ax.get_xlim()
        t = np.geomspace(lo, hi, 50)
        ax.loglog(
            t,
            n_cfg * 1e6 / np.sqrt(t),
            ":",
            lw=1.0,
            color="k",
            label=f"configured N = {n_cfg * 1e6:.1f} µg/√Hz",
        )
    ax.set(xlabel="tau, s", ylabel="Allan deviation, µg", title="(c) Allan deviation")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="lower left")
