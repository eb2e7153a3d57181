"""Figure of the zero-motion check (paper Fig. 4): time trace and ASD.

Kept apart from :mod:`noise_check` so computing the statistics never imports
matplotlib; the report reuses :func:`plot_noise_check` on a
:class:`~sdt_framework.chain.NoiseCheck`.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from scipy import signal

from ..io import atomic_path
from .noise_check import BAND_HZ, NoiseCheck

__all__ = ["plot_noise_check"]


def plot_noise_check(result: NoiseCheck, path: str | os.PathLike[str]) -> Path:
    """Save a two-panel figure of ``result`` to ``path`` (format from its suffix).

    (a) the first window of each signal in mg against time in ms; (b) its
    amplitude spectral density (Welch, ``nperseg = window_length``) in
    ug/sqrt(Hz), with the 10..1500 Hz NSD band shaded and each mean NSD drawn.
    Uses the Agg backend through ``matplotlib.figure.Figure`` (no pyplot state).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10, 4), layout="constrained")
    FigureCanvasAgg(fig)
    ax_t, ax_f = fig.subplots(1, 2)
    series = [("SDT " + result.sensor, result.sdt_signal, result.sdt_fs, result.sdt, "C0")]
    if result.recording is not None and result.recording_signal is not None:
        series.insert(
            0, ("recording", result.recording_signal, result.recording_fs, result.recording, "0.5")
        )
    n = result.window_length
    for name, x, fs, stats, colour in series:
        assert fs is not None
        window = x[:n] - np.mean(x[:n])
        ax_t.step(
            np.arange(n) / fs * 1e3, window * 1e3, where="post", lw=0.6, color=colour, label=name
        )
        used = x[: result.n_windows * n]
        freqs, psd = signal.welch(used, fs=fs, nperseg=n)
        ax_f.semilogy(
            freqs[1:],
            np.sqrt(psd[1:]) * 1e6,
            lw=0.8,
            color=colour,
            label=f"{name}: NSD {stats.nsd_ug_rthz.mean():.1f} µg/√Hz",
        )
        ax_f.axhline(stats.nsd_ug_rthz.mean(), color=colour, ls="--", lw=0.8)
    ax_t.set(
        xlabel="time, ms",
        ylabel="acceleration, mg",
        title="(a) zero-motion noise",
        xlim=(0, min(50.0, n / result.sdt_fs * 1e3)),
    )
    ax_f.axvspan(*BAND_HZ, color="0.9", zorder=0)
    ax_f.set(xlabel="frequency, Hz", ylabel="ASD, µg/√Hz", title="(b) amplitude spectral density")
    for ax in (ax_t, ax_f):
        ax.legend(fontsize=8, loc="upper right")
        ax.grid(alpha=0.3)
    path = Path(path)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=120)
    return path
