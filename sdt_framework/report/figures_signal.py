"""Signal figures: the SDT on one recording (paper Fig. 2) and zero-motion noise (Fig. 4).

Both draw data prepared by :mod:`.signals`; the noise figure reuses the
zero-motion check of :class:`sdt_framework.validation.NoiseCheck` (the same
Welch settings as ``sdt validate-noise --plot``) but puts every noisy profile
in one figure with the report's sensor colours, and reads each NSD over the
band that profile's chain passes, not over a fixed 10-1500 Hz.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from matplotlib.figure import Figure
from scipy import signal

from ..validation.noise_plot import draw_noise
from .signals import BandNoise, SensorTrace
from .style import LINESTYLES, figure_label, new_figure

__all__ = ["plot_noise", "plot_sdt_overlay"]


def _asd(x: np.ndarray, fs: float) -> tuple[np.ndarray, np.ndarray]:
    """Welch ASD in g/sqrt(Hz), ~0.1 s segments (a power of two), Hann, 50 % overlap."""
    nperseg = int(min(len(x), 2 ** round(np.log2(max(fs * 0.1, 16)))))
    freqs, psd = signal.welch(x, fs=fs, nperseg=nperseg)
    return freqs[1:], np.sqrt(psd[1:])


def plot_sdt_overlay(
    traces: Sequence[SensorTrace],
    colors: dict[str, str],
    *,
    span_s: float = 0.08,
    title: str = "",
) -> Figure:
    """(a) Time-domain overlay around the largest peak; (b) Welch ASD, log-log.

    Parameters
    ----------
    traces
        One :class:`SensorTrace` per sensor, the reference first (it sets the
        time of the peak; the others keep their own causal-filter delay).
    colors
        Sensor colours (see :func:`.style.sensor_colors`).
    span_s
        Width of the time window shown, s (centred on the reference's largest |x|).
    title
        Figure title, e.g. the recording name.
    """
    fig = new_figure(12, 4.6)
    ax_t, ax_f = fig.subplots(1, 2)
    first = traces[0]
    peak = int(np.argmax(np.abs(first.signal))) / first.fs
    start = max(0.0, peak - span_s / 2)
    for i, trace in enumerate(traces):
        t = np.arange(len(trace.signal)) / trace.fs
        shown = (t >= start) & (t <= start + span_s)
        color = colors.get(trace.sensor)
        style = LINESTYLES[i % len(LINESTYLES)]
        label = figure_label(trace.sensor) + (" (clipped)" if trace.clipped else "")
        ax_t.plot(
            (t[shown] - start) * 1e3,
            trace.signal[shown],
            color=color,
            ls=style,
            lw=1.0 if i else 0.8,
            label=label,
        )
        if trace.clipped:
            for level in (-trace.full_scale_g, trace.full_scale_g):
                ax_t.axhline(level, color=color, ls=":", lw=0.9)
            ax_t.annotate(
                f"±{trace.full_scale_g:g} g",
                (1.0, trace.full_scale_g),
                color=color,
                xycoords=("axes fraction", "data"),
                ha="right",
                va="bottom",
                fontsize=8,
            )
        freqs, asd = _asd(trace.signal, trace.fs)
        ax_f.loglog(
            freqs,
            asd,
            color=color,
            ls=style,
            lw=1.0,
            label=f"{figure_label(trace.sensor)} ({trace.fs:g} Hz)",
        )
    ax_t.set(
        xlabel=f"time from {start * 1e3:.0f} ms, ms",
        ylabel="acceleration, g",
        title="(a) time domain around the largest peak",
    )
    ax_f.set(
        xlabel="frequency, Hz", ylabel="ASD, g/√Hz", title="(b) amplitude spectral density (Welch)"
    )
    for ax in (ax_t, ax_f):
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8, loc="lower left" if ax is ax_f else "upper right")
    if title:
        fig.suptitle(title, fontsize=11)
    return fig


def plot_noise(noise: Sequence[BandNoise], colors: dict[str, str]) -> Figure:
    """(a) First 50 ms of each profile's zero-motion output, mg; (b) its ASD, µg/√Hz.

    Every noisy profile in one figure with the report's sensor colours, drawn by
    :func:`sdt_framework.validation.noise_plot.draw_noise` as ``sdt
    validate-noise --plot`` draws one, except that each mean NSD is read, and
    dashed, over the band that profile's chain passes (:class:`.signals.BandNoise`).
    """
    fig = new_figure(12, 4.4)
    ax_t, ax_f = fig.subplots(1, 2)
    checks = [n.check for n in noise]
    series = [
        (
            n.check.sensor,
            n.check.sdt_signal,
            n.check.sdt_fs,
            n.check.sdt,
            colors.get(n.check.sensor),
            LINESTYLES[i % len(LINESTYLES)],
        )
        for i, n in enumerate(noise)
    ]
    if len({(c.window_length, c.n_windows) for c in checks}) > 1:
        raise ValueError("noise checks with different windowing cannot share one figure")
    if checks:
        draw_noise(ax_t, ax_f, series, checks[0], bands=[n.check.band_hz for n in noise])
    ax_t.set_title("(a) zero-motion noise (SDT, x_ref = 0)")
    ax_f.set_title("(b) ASD; each NSD dashed over the band its chain passes")
    return fig
