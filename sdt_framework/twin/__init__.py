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

Public API
----------
load_pair(path, sensor, *, axes, device_channel, reference_channel, readers) -> Pair
    A recorder file of channels (enDAQ IDE, or any reader listing channels) or a pair
    ``.toml``, read through the readers handed down; ``Pair``, ``Signal`` its sides.
require_rate(sensor) ; check_reference_scale(factor) ; scaled_reference(pair, factor)
    The refusals before any file is read, and ``--reference-scale`` applied.
check_twin(pair, sensor) -> CheckResult
    Frozen dataclasses all the way down (``PairInfo``, ``AlignmentInfo``, ``Band``,
    ``Floor``, ``Distortion``, ``Clipping``, ``Calibration``, ``Summary``);
    ``as_dict()`` is ``sdt twin check --json``; ``rate_setting`` the device's rate
    against the part's nearest setting (:func:`rate_setting`, :class:`RateSetting`).
plot_check(result, path) ; describe(clipped_side)
    The check's figure; a side's clipped samples in words.
fit_twin(pair, sensor, name) -> FitResult ; profile_toml(result) ; profile_name(name, base, known)
    The fitted profile, its sensor file, and its name (one that shadows no known sensor).
"""

from __future__ import annotations

from .align import require_rate
from .check import MARGIN_DB, REFERENCE_LIMIT, check_twin
from .clipping import ClippedSide, Clipping, describe
from .fit import FitResult, default_name, fit_twin, profile_name, profile_toml
from .pair import load_pair
from .plot import plot_check
from .results import (
    AlignmentInfo,
    Band,
    CheckResult,
    CheckSpectra,
    DeviceInfo,
    Distortion,
    Floor,
    PairInfo,
    SideInfo,
    Summary,
)
from .signals import Pair, Signal, scaled_reference
from .transfer import Transfer
from .verdict import SCALE_RANGE, Calibration, RateSetting, check_reference_scale, rate_setting

__all__ = [
    "MARGIN_DB",
    "REFERENCE_LIMIT",
    "SCALE_RANGE",
    "AlignmentInfo",
    "Band",
    "Calibration",
    "CheckResult",
    "CheckSpectra",
    "ClippedSide",
    "Clipping",
    "DeviceInfo",
    "Distortion",
    "FitResult",
    "Floor",
    "Pair",
    "PairInfo",
    "RateSetting",
    "SideInfo",
    "Signal",
    "Summary",
    "Transfer",
    "check_reference_scale",
    "check_twin",
    "default_name",
    "describe",
    "fit_twin",
    "load_pair",
    "plot_check",
    "profile_name",
    "profile_toml",
    "rate_setting",
    "require_rate",
    "scaled_reference",
]
