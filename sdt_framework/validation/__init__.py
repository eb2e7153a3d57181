"""Validating the chain at zero motion: noise statistics and Allan deviation (paper 3.1, Table 2).

The chain of :mod:`sdt_framework.chain` is run on x_ref = 0 and what comes out
is compared with the profile (and with a recording at rest, if one is given):
noise density, RMS, ASD, and the Allan deviation's white-noise level and
floor. This package sits beside ``chain``, above it; nothing in the chain
imports it.

Where plots live (one rule for the package): a figure is drawn in the package
whose results it shows, in its ``*_plot.py`` module, on axes it is given or
into a file it is named (here ``noise_plot.py`` and ``allan_plot.py``; also
``twin/plot.py`` and ``verdict/cdplot.py``). :mod:`sdt_framework.report`
draws the benchmark's own figures and composes the document, reusing these
``draw_*`` functions.

Public API
----------
noise_check(sensor, ...), NoiseCheck, window_stats, WindowStats
    The zero-motion noise check and the statistics of its windows.
zero_motion_cost(sensor, fs_ref, n_windows, window_length)
    What a check costs before it runs (input samples, peak bytes, seconds).
plot_noise_check(result, path, allan=None) ; plot_formats()
    Its figure (matplotlib Agg, no pyplot state); the file formats a figure may be saved in.
allan_curve(x, fs), AllanCurve, allan_check(check, sensor), AllanCheck ; allan_seconds(n)
    The Allan deviation of a zero-motion signal and its read-off against the profile; the
    estimated run time of one curve of n samples.
"""

from __future__ import annotations

from .allan import AllanCurve, allan_curve, allan_seconds
from .allan_check import AllanCheck, allan_check
from .noise_check import NoiseCheck, WindowStats, noise_check, window_stats, zero_motion_cost
from .noise_plot import plot_formats, plot_noise_check

__all__ = [
    "AllanCheck",
    "AllanCurve",
    "NoiseCheck",
    "WindowStats",
    "allan_check",
    "allan_curve",
    "allan_seconds",
    "noise_check",
    "plot_formats",
    "plot_noise_check",
    "window_stats",
    "zero_motion_cost",
]
