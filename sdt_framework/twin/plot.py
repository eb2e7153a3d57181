"""The figures of ``sdt twin check``: spectra of reference, twin and device; the transfer.

(a) Amplitude spectral densities of the reference, the twin and the real device
on the axis with the most motion, judgeable bands shaded. (b) The transfer
function twin -> device (gain in dB; 0 dB is a perfect twin) with its
coherence. Drawn with the Agg backend through ``matplotlib.figure.Figure`` (no
pyplot state), saved atomically; the figures live with the check they draw,
as the zero-motion check's do (``validation.noise_plot``).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..io import atomic_path
from .results import CheckResult

__all__ = ["plot_check"]


def plot_check(result: CheckResult, path: str | os.PathLike[str]) -> Path:
    """Draw ``result``'s two panels into ``path`` (format from its suffix)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    sp = result.spectra
    if sp is None:
        raise ValueError("a check without its spectra (built by hand?) has nothing to draw")
    main = sp.main
    axis = sp.axes[main]
    fig = Figure(figsize=(11, 4.2), layout="constrained")
    FigureCanvasAgg(fig)
    ax_a, ax_h = fig.subplots(1, 2)
    ug = 1e6
    ax_a.loglog(sp.f_ref[1:], ug * np.sqrt(sp.reference[main, 1:]), color="0.6",
                lw=0.8, label="reference")  # fmt: skip
    ax_a.loglog(sp.f[1:], ug * np.sqrt(sp.device[main, 1:]), color="C3", lw=0.9,
                label="real device")  # fmt: skip
    ax_a.loglog(sp.f[1:], ug * np.sqrt(sp.twin[main, 1:]), color="C0", lw=0.9,
                label=f"twin ({result.pair.sensor})")  # fmt: skip
    for band in (b for b in sp.judged if b.axis == axis):
        ax_a.axvspan(band.f_lower_hz, band.f_upper_hz, color="C2", alpha=0.12, lw=0)
    ax_a.set(xlabel="frequency, Hz", ylabel="ASD, µg/√Hz", xlim=(5, sp.f[-1]),
             title=f"(a) {result.pair.file}, axis {axis} (judgeable bands shaded)")  # fmt: skip
    ax_a.legend(loc="lower left", fontsize=8)
    f = sp.f_h[1:]
    ax_h.semilogx(f, 20 * np.log10(np.abs(sp.h[main, 1:]) + 1e-30), color="C0", lw=0.9)
    ax_h.axhline(0, color="0.3", lw=0.6)
    ax_h.set(xlabel="frequency, Hz", ylabel="twin -> device gain, dB", ylim=(-30, 30),
             title="(b) transfer function and coherence")  # fmt: skip
    ax_c = ax_h.twinx()
    ax_c.semilogx(f, sp.coherence[main, 1:], color="C1", lw=0.7, alpha=0.8)
    ax_c.set(ylabel="coherence", ylim=(0, 1.05))
    path = Path(path)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=110)
    return path
