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
plot_noise_check(result, path, allan=None)
    Its figure (matplotlib Agg, no pyplot state).
allan_curve(x, fs), AllanCurve, allan_check(check, sensor), AllanCheck
    The Allan deviation of a zero-motion signal and its read-off against the profile.
"""

from __future__ import annotations

from .allan import AllanCurve, allan_curve
from .allan_check import AllanCheck, allan_check
from .noise_check import NoiseCheck, WindowStats, noise_check, window_stats
from .noise_plot import plot_noise_check

__all__ = [
    "AllanCheck",
    "AllanCurve",
    "NoiseCheck",
    "WindowStats",
    "allan_check",
    "allan_curve",
    "noise_check",
    "plot_noise_check",
    "window_stats",
]
