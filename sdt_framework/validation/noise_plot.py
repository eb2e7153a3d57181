"""Figure of the zero-motion check (paper Fig. 4): time trace and ASD.

Kept apart from :mod:`noise_check` so computing the statistics never imports
matplotlib; the report draws its Fig. 4 with the same :func:`draw_noise`.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from scipy import signal

from ..io import atomic_path
from .noise_check import NoiseCheck, WindowStats

if TYPE_CHECKING:
    from .allan_check import AllanCheck

__all__ = ["NoiseSeries", "draw_noise", "plot_formats", "plot_noise_check"]

#: matplotlib formats left out: pgf needs LaTeX, raw/rgba are pixel dumps no viewer opens
_NOT_OFFERED = frozenset({"pgf", "raw", "rgba"})


def plot_formats() -> tuple[str, ...]:
    """Extensions ``plot_noise_check`` writes: png, pdf, svg first, then matplotlib's others.

    Checked before the computation, so a typo in ``--plot`` costs nothing.
    """
    from matplotlib.backend_bases import FigureCanvasBase

    first = ("png", "pdf", "svg")
    found = set(FigureCanvasBase.get_supported_filetypes()) - _NOT_OFFERED
    return tuple(f for f in first if f in found) + tuple(sorted(found - set(first)))


#: one curve of the noise figure: label, signal (g), rate (Hz), its statistics, colour, line style
NoiseSeries = tuple[str, np.ndarray, float, WindowStats, str | None, str]


def draw_noise(
    ax_t: Any,
    ax_f: Any,
    series: Sequence[NoiseSeries],
    check: NoiseCheck,
    bands: Sequence[tuple[float, float]] | None = None,
) -> None:
    """Draw zero-motion noise on two axes: (a) time trace in mg, (b) ASD in ug/sqrt(Hz).

    Shared by ``sdt validate-noise --plot`` and the report's Fig. 4, so both show
    the statistics the same way: the first ``check.window_length`` samples
    (mean removed, at most 50 ms), the Welch ASD with ``nperseg = window_length``
    over the ``check.n_windows`` windows, the NSD band (``check.band_hz``) shaded and
    each mean NSD dashed. With ``bands`` (one per series, the band its NSD was
    measured over) each mean NSD is dashed over its own band only and no band
    is shaded: the report's Fig. 4 clips each band to what the chain passes.
    """
    n = check.window_length
    for i, (label, x, fs, stats, colour, style) in enumerate(series):
        window = x[:n] - np.mean(x[:n])
        t_ms = np.arange(n) / fs * 1e3
        shown = t_ms <= 50.0
        ax_t.step(
            t_ms[shown],
            window[shown] * 1e3,
            where="post",
            lw=0.7,
            color=colour,
            ls=style,
            label=f"{label}: RMS {stats.rms_mg.mean():.2f} mg",
        )
        freqs, psd = signal.welch(x[: check.n_windows * n], fs=fs, nperseg=n)
        nsd = stats.nsd_ug_rthz.mean()
        own = f" over {bands[i][0]:g}–{bands[i][1]:.0f} Hz" if bands is not None else ""
        ax_f.loglog(
            freqs[1:],
            np.sqrt(psd[1:]) * 1e6,
            lw=0.8,
            color=colour,
            label=f"{label}: NSD {nsd:.1f} µg/√Hz{own}",
        )
        if bands is None:
            ax_f.axhline(nsd, color=colour, ls="--", lw=0.8)
        else:
            ax_f.hlines(nsd, *bands[i], color=colour, ls="--", lw=1.2)
    if bands is None:
        lo, hi = check.band_hz
        ax_f.axvspan(lo, hi, color="0.92", zorder=0, label=f"NSD band {lo:g}–{hi:.0f} Hz")
    ax_t.set(xlabel="time, ms", ylabel="acceleration, mg")
    ax_f.set(xlabel="frequency, Hz", ylabel="ASD, µg/√Hz", title="(b) amplitude spectral density")
    for ax, where in ((ax_t, "upper right"), (ax_f, "lower left")):
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8, loc=where)


def plot_noise_check(
    result: NoiseCheck, path: str | os.PathLike[str], allan: AllanCheck | None = None
) -> Path:
    """Save a two-panel figure of ``result`` (three with ``allan``) to ``path``.

    The SDT's zero-motion noise and, when the check has one, the recording's
    (see :func:`draw_noise`); with ``allan``, a third panel of their Allan
    deviation (:func:`~sdt_framework.chain.allan_plot.draw_allan`). Uses the
    Agg backend through ``matplotlib.figure.Figure`` (no pyplot state).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10, 4) if allan is None else (15, 4.5), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(1, 2 if allan is None else 3)
    ax_t, ax_f = axes[:2]
    series: list[NoiseSeries] = []
    if result.recording is not None and result.recording_signal is not None:
        assert result.recording_fs is not None
        series.append(
            (
                "recording",
                result.recording_signal,
                result.recording_fs,
                result.recording,
                "0.5",
                "-",
            )
        )
    series.append(("SDT " + result.sensor, result.sdt_signal, result.sdt_fs, result.sdt, "C0", "-"))
    draw_noise(ax_t, ax_f, series, result)
    ax_t.set_title("(a) zero-motion noise")
    if allan is not None:
        from .allan_plot import draw_allan

        draw_allan(axes[2], allan)
    path = Path(path)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=path.suffix.lstrip(".") or "png", dpi=120)
    return path
