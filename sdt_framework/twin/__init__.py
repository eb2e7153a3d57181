"""The twin against real hardware: check a sensor's twin on a paired recording, fit one.

A *pair* is one vibration measured at once by a reference (a piezo, fast and
quiet) and by a real device (the MEMS part the twin models), on one clock.
:func:`check_twin` runs the reference through the twin and compares the result
with what the device recorded, band by band, after estimating everything that
is not the twin's fault (the device's real output rate, the time offset, the
sign and the mounting's axis alignment). :func:`fit_twin` estimates from the
pair the profile values the data can support and writes an ordinary sensor
profile with provenance. This package sits above ``chain`` and ``data`` and
uses them; nothing below imports it. Its figure is drawn here (``plot.py``),
as every package draws the figures of its own results (see :mod:`sdt_framework.report`).
"""

from __future__ import annotations

from .check import CheckResult, check_twin
from .fit import FitResult, fit_twin, profile_toml
from .pair import load_pair
from .signals import Pair, Signal

__all__ = [
    "CheckResult",
    "FitResult",
    "Pair",
    "Signal",
    "check_twin",
    "fit_twin",
    "load_pair",
    "profile_toml",
]
