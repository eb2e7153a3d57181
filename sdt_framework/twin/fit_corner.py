"""The anti-alias corner a pair can see, fitted jointly with the gain.

A corner shapes the response only near itself: a first-order low-pass is
-1 dB at half its corner, -0.26 dB at a quarter. So the corner is fitted only
from strong judgeable bands (device level at least :data:`STRONG` times the
base twin's noise in the band) on the axis with the most of them, and only
when the bands reach where the base corner acts. For a candidate corner
``fc`` the twin is rerun and aligned (:func:`.align.align`, as the check does,
so the corner's phase is not charged to anything) and its band levels compared
with the device's in dB; the gain that best fits those is taken in closed
form (the mean dB difference), and ``fc`` minimises what is left
(:func:`scipy.optimize.minimize_scalar`, bounded, on log fc, between a
quarter and four times the base corner and below the reference's band
limit). Its standard uncertainty comes from the cost's curvature at the
optimum (``var = 2 s^2 / S''``, ``s^2`` the residual variance). An optimum
at a bound, or one whose uncertainty exceeds half its value, determines
nothing: the corner is kept at the base's value, and the fit says why.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy import optimize

from ..specs import SensorSpec
from . import spectra
from .align import align
from .check import REFERENCE_LIMIT
from .results import CheckResult
from .signals import Pair

__all__ = ["STRONG", "fit_corner"]

#: a band counts for the corner when the device's level is this many times the base's noise
STRONG = 10.0
#: the bands must reach this share of the base corner, where a first-order filter is -1 dB
REACH = 0.5


def _levels(pair: Pair, spec: SensorSpec, axis: int, bands: np.ndarray) -> np.ndarray:
    """Twin band RMS of ``spec`` on ``axis`` in ``bands`` (lower, centre, upper): the twin
    run and aligned as :func:`.check.check_twin` does, then only its band levels."""
    a = align(pair, spec)
    f, density = spectra.psd(a.twin[axis : axis + 1], a.rate_hz)
    return spectra.band_rms(f, density, bands)[0]


def _with_corner(base: SensorSpec, corner_hz: float) -> SensorSpec:
    return base.model_validate({**base.content_dict(), "analog_cutoff_hz": float(corner_hz)})


def fit_corner(
    pair: Pair, base: SensorSpec, check: CheckResult
) -> tuple[dict[str, Any] | None, dict[str, Any] | None, str]:
    """(corner entry, joint gain entry, "") or (None, None, why not) for ``analog_cutoff_hz``."""
    fc0 = base.analog_cutoff_hz
    if fc0 is None:
        return None, None, "the base profile has no analog corner"
    nsd = base.noise_density_ug_rthz * 1e-6
    strong = [
        b for b in check.bands
        if b.judgeable
        and b.real_rms_g >= STRONG * nsd * np.sqrt(b.f_upper_hz - b.f_lower_hz)
    ]  # fmt: skip
    if not strong:
        return None, None, "no judgeable band stands above the part's noise"
    axis = max({b.axis for b in strong}, key=lambda a: sum(b.axis == a for b in strong))
    rows = [b for b in strong if b.axis == axis]
    top = max(b.f_centre_hz for b in rows)
    if len(rows) < 3 or top < REACH * fc0:
        return (
            None,
            None,
            (
                f"the strong judgeable bands ({len(rows)} on {axis}) end at {top:.0f} Hz, below "
                f"{REACH:g} x the base's {fc0:g} Hz, where the corner shapes nothing"
            ),
        )
    index = pair.device.axes.index(axis)
    bands = np.array([[b.f_lower_hz, b.f_centre_hz, b.f_upper_hz] for b in rows])
    real_db = 20 * np.log10([b.real_rms_g for b in rows])

    def residual(log_fc: float) -> np.ndarray:
        twin_db = 20 * np.log10(_levels(pair, _with_corner(base, np.exp(log_fc)), index, bands))
        diff = real_db - twin_db
        return diff - diff.mean()  # the gain, in closed form, taken out

    lo = np.log(fc0 / 4)
    hi = np.log(min(4 * fc0, REFERENCE_LIMIT * pair.reference.rate_hz))

    def cost_at(log_fc: float) -> float:
        return float(np.sum(residual(log_fc) ** 2))  # one twin run per evaluation

    best = optimize.minimize_scalar(cost_at,
                                    bounds=(lo, hi), method="bounded",
                                    options={"xatol": 1e-3})  # fmt: skip
    x, cost = float(best.x), float(best.fun)
    if min(x - lo, hi - x) < 0.02:
        return (
            None,
            None,
            (
                f"the best corner lies at the search's bound ({np.exp(x):.0f} Hz): these bands "
                f"are not shaped like a first-order corner"
            ),
        )
    h = 0.05
    costs = [cost_at(x + d) for d in (-h, h)]
    curvature = (costs[0] - 2 * cost + costs[1]) / h**2
    s2 = max(cost, 1e-12) / (len(rows) - 2)  # two parameters: corner and gain
    se_log = float(np.sqrt(2 * s2 / curvature)) if curvature > 0 else float("inf")
    corner = float(np.exp(x))
    if not se_log < 0.5:
        return None, None, f"the corner ({corner:.0f} Hz) is determined only to +-{se_log:.0%}"
    fitted = _with_corner(base, corner)
    twin_db = 20 * np.log10(_levels(pair, fitted, index, bands))
    gain_db = float(np.mean(real_db - twin_db))
    span = f"{len(rows)} strong judgeable bands of axis {axis}, {rows[0].f_lower_hz:.0f}-" \
        f"{rows[-1].f_upper_hz:.0f} Hz"  # fmt: skip
    gain_se_db = float(np.sqrt(s2 / len(rows)))
    gain = 10 ** (gain_db / 20)
    return (
        {"value": corner, "uncertainty": corner * se_log,
         "from": f"{span}, jointly with the gain"},
        {"value": 100 * (gain - 1), "uncertainty": 100 * gain * gain_se_db * np.log(10) / 20,
         "from": f"{span}, jointly with analog_cutoff_hz"},
        "",
    )  # fmt: skip
