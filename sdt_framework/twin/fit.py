"""``sdt twin fit``: the profile values a pair can support, with uncertainties and provenance.

Fitted (each with its standard uncertainty and the data it came from):

- **output rate**: the device's timestamps (least-squares slope, its standard
  error from the fit); the digital corner moves with it (:func:`.align.at_rate`);
- **sensitivity (gain) error** of the axis with the most judgeable bands:
  least squares of the device's band RMS on the twin's over those bands
  (standard error from the residuals); written as a ``scale`` stage. Only
  with :data:`MIN_BANDS` judgeable bands or more (a recording at rest has none);
- **noise density** of each axis: the device's floor (median amplitude
  density of the tone-free bins from 10 Hz to a quarter of its rate, where
  the part's own filters are flat), less the twin's quantisation noise
  (``D^2/12`` spread over the Nyquist band); uncertainty: the standard error
  of that median. The profile takes the quietest axis; an axis more than 10 %
  noisier gets its own figure (``per_axis``). Each floor's slope (dB per
  decade) is reported: a profile's noise is white, so a slope is stated, not
  modelled.

- **anti-alias corner** (``analog_cutoff_hz``) jointly with the gain, where
  the strong judgeable bands reach the corner (:mod:`.fit_corner`); the gain
  then comes from the same joint fit.

Not determined, left at the base profile's values and said so: the
mechanical corner (a 5 kHz reference judges up to 2 kHz, far below these
parts' resonances), full scale and resolution (datasheet settings), and the
axis alignment (the mounting's, not the part's: reported by ``check``).
"""

from __future__ import annotations

import datetime as dt
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..errors import SDTError
from ..specs import _NAME, SensorSpec
from ..units import TO_G, UNITS
from . import spectra
from .align import at_rate
from .check import check_twin
from .fit_corner import fit_corner
from .pair import Pair
from .results import CheckResult

__all__ = [
    "MIN_BANDS",
    "SCALE_RANGE",
    "FitResult",
    "default_name",
    "fit_twin",
    "profile_name",
    "profile_toml",
]

#: judgeable bands needed on one axis before a gain is fitted
MIN_BANDS = 3
#: a fitted gain (device / twin) outside this range is no part's sensitivity error
SCALE_RANGE = (0.5, 2.0)
#: unit mix-ups a gain far from 1 points at: ratio (device / twin) -> what the device's values
#: probably are (one unit read as g, or g read as another)
UNIT_RATIOS = {
    TO_G[declared] / TO_G[actual]: f"in {actual}, declared as {declared}"
    for other in UNITS[1:]
    for actual, declared in ((other, "g"), ("g", other))
}


@dataclass
class FitResult:
    """Fitted values (value, uncertainty, from), what was left at the base, and the profile."""

    fitted: dict[str, dict[str, Any]]
    kept: dict[str, str]
    profile: dict[str, Any]  # the [sensor] table
    provenance: list[str]


def _rate(pair: Pair) -> dict[str, Any]:
    """The device's rate: least-squares slope of its timestamps, with that slope's standard
    error (NaN for a pair built from arrays, which carry no timestamps). The error treats the
    timestamps' scatter about the line as independent: a clock step or a drift (a channel
    that was resampled says so in its note) makes it optimistic."""
    dev = pair.device
    return {"value": dev.rate_hz, "uncertainty": dev.rate_sd_hz,
            "from": f"timestamps of {dev.label} ({dev.values.shape[1]} samples)"}  # fmt: skip


def _noise(pair: Pair, sensor: SensorSpec) -> dict[str, dict[str, Any]]:
    """Noise density and floor slope of each axis of the device."""
    dev = pair.device
    f, p = spectra.psd(dev.values, dev.rate_hz)
    hi = dev.rate_hz / 4
    step = sensor.quantisation_step_g
    q2 = (step**2 / 12) / (dev.rate_hz / 2) if step else 0.0
    out = {}
    for axis, row, tones in zip(dev.axes, p, spectra.tone_bins(p), strict=True):
        free = (f >= 10) & (f <= hi) & ~tones
        asd = np.sqrt(row[free])
        floor = float(np.median(asd))
        out[axis] = {
            "value": 1e6 * float(np.sqrt(max(floor**2 - q2, 0.0))),
            "uncertainty": 1e6 * float(1.2533 * asd.std() / np.sqrt(len(asd))),  # median's SE
            "slope_db_per_decade": float(np.polyfit(np.log10(f[free]), 20 * np.log10(asd), 1)[0]),
            "from": f"median floor of axis {axis}, {len(asd)} tone-free bins 10-{hi:.0f} Hz, "
            f"less quantisation",
        }
    return out


def _gain(pair: Pair, check: CheckResult) -> tuple[dict[str, Any] | None, str]:
    """The scale error of the axis with the most judgeable bands, or None and why not."""
    counts = {a: sum(b.judgeable and b.axis == a for b in check.bands) for a in pair.device.axes}
    axis = max(counts, key=counts.__getitem__)
    rows = [b for b in check.bands if b.judgeable and b.axis == axis]
    if len(rows) < MIN_BANDS:
        return None, f"only {len(rows)} judgeable band(s) on any axis (at least {MIN_BANDS})"
    if check.calibration.reference_off:
        k = check.calibration
        return None, (
            f"the device reads gravity as {k.static_g:.3f} g, so the x{k.tone_gain:.3f} "
            f"gain disagreement at {k.tone_hz:.0f} Hz is the reference's calibration, "
            f"not the part's"
        )
    real = np.array([b.real_rms_g for b in rows])
    twin = np.array([b.twin_rms_g for b in rows])
    gain = float(real @ twin / (twin @ twin))  # least squares, real ~ gain x twin
    residual = real - gain * twin
    se = float(np.sqrt(residual @ residual / (len(rows) - 1) / (twin @ twin)))
    return {
        "value": 100 * (gain - 1), "uncertainty": 100 * se,
        "from": f"{len(rows)} judgeable bands of axis {axis}, "
                f"{rows[0].f_lower_hz:.0f}-{rows[-1].f_upper_hz:.0f} Hz",
    }, ""  # fmt: skip


def default_name(base: SensorSpec) -> str:
    """``NAME-fitted`` for a base profile, a part's mode spelt without brackets (a profile
    named ``adxl355[odr=4000]-fitted`` could not be asked for again by name)."""
    return re.sub(r"[^a-z0-9._-]+", "-", base.name).strip("-") + "-fitted"


def profile_name(name: str | None, base: SensorSpec, known: Callable[[str], bool]) -> str:
    """The fitted profile's name (``name``, or :func:`default_name`): one ``--sensor NAME``
    finds again, naming nothing ``known`` (built in or loaded: a fitted profile must not
    shadow it); else a one-line :class:`SDTError` with a name that would do."""
    chosen = name if name is not None else default_name(base)
    shown = repr(chosen if len(chosen) <= 40 else chosen[:39] + "\u2026")
    other = default_name(base) + ("-2" if chosen == default_name(base) else "")
    if not _NAME.fullmatch(chosen):
        raise SDTError(
            f"--name {shown}: a profile name is lower-case letters, digits, '.', '_' or '-', "
            f"starting with a letter or a digit (so that --sensor NAME finds it again); "
            f"e.g. {other}"
        )
    if known(chosen):
        raise SDTError(
            f"--name {shown}: a sensor of that name is already known (built in or loaded); a "
            f"fitted profile must not shadow it: choose another, e.g. {other}"
        )
    return chosen


def _plausible(gain: dict[str, Any], pair: Pair) -> None:
    """Refuse a fitted scale no part has (a device in other units than declared)."""
    ratio = 1 + gain["value"] / 100
    lo, hi = SCALE_RANGE
    if lo <= ratio <= hi:
        return
    near = min(UNIT_RATIOS, key=lambda r: abs(np.log(max(ratio, 1e-300) / r)))
    hint = (
        f"; the device's values look {UNIT_RATIOS[near]} (fix its units)"
        if ratio > 0 and abs(np.log(ratio / near)) < np.log(1.2)
        else "; check the device's and the reference's units"
    )
    raise SDTError(
        f"{pair.name}: the fitted scale error is {gain['value']:+,.0f} % (device / twin = "
        f"{ratio:.4g}), outside a part's plausible {lo:g}x to {hi:g}x{hint}"
    )


def fit_twin(pair: Pair, base: SensorSpec, name: str | None = None) -> FitResult:
    """Fit ``base``'s twin to ``pair``; the result's profile runs like any sensor file."""
    if not isinstance(base.sampling_rate_hz, float) or not base.inject_noise:
        raise SDTError(
            f"{base.name} cannot be fitted from {pair.name}: it has no output rate or no "
            f"noise of its own (a reference chain); fit the profile of a device part"
        )
    fitted: dict[str, dict[str, Any]] = {"sampling_rate_hz": _rate(pair)}
    noise = _noise(pair, base)
    quietest = min(noise, key=lambda a: noise[a]["value"])
    fitted["noise_density_ug_rthz"] = noise[quietest]
    for axis, entry in noise.items():
        fitted[f"noise_density_ug_rthz[{axis}]"] = entry
        fitted[f"noise_slope_db_per_decade[{axis}]"] = {
            "value": entry["slope_db_per_decade"], "uncertainty": None,
            "from": "least-squares slope of the same bins, dB per decade (0: white); "
                    "stated, not modelled (a profile's noise is white)",
        }  # fmt: skip
    kept = {
        "mech_cutoff_hz": "the judgeable bands end below it",
        "analog_cutoff_hz": "",
        "full_scale_g": "a datasheet setting",
        "adc_bits": "a datasheet setting",
        "alignment": "the mounting's, not the part's (see sdt twin check)",
    }
    stages: list[dict[str, Any]] = []
    try:
        check = check_twin(pair, base)
    except SDTError as exc:
        check, why = None, str(exc).split(": ", 1)[-1][:90] + "..."
        kept["analog_cutoff_hz"] = why
    gain = None
    if check is not None:
        gain, why = _gain(pair, check)
        corner, joint, why_corner = fit_corner(pair, base, check)
        if corner is None:
            kept["analog_cutoff_hz"] = why_corner
        else:
            del kept["analog_cutoff_hz"]
            fitted["analog_cutoff_hz"] = corner
            gain = joint if gain is not None else None
    if gain is None:
        kept["scale"] = why
    else:
        _plausible(gain, pair)
        fitted["scale_error_pct"] = gain
        stages.append({"name": "scale", "params": {"error_pct": round(gain["value"], 3)}})
    clocked = at_rate(base, fitted["sampling_rate_hz"]["value"])
    table = {k: v for k, v in base.content_dict().items() if v is not None}
    table.update(
        name=name or default_name(base),
        description=f"{base.description} (fitted on {pair.name})",
        source=f"sdt twin fit: {pair.name} (sha256 {pair.digest}), {pair.reference.label} -> "
        f"{pair.device.label}, {dt.date.today().isoformat()}; base profile {base.name}",
        sampling_rate_hz=round(float(clocked.sampling_rate_hz), 3),
        noise_density_ug_rthz=round(noise[quietest]["value"], 2),
    )
    louder = {
        a: e["value"] for a, e in noise.items() if e["value"] > 1.1 * noise[quietest]["value"]
    }
    if louder:  # axes more than 10 % noisier than the quietest get their own figure
        table["per_axis"] = {a: {"noise_density_ug_rthz": round(v, 2)} for a, v in louder.items()}
    if "analog_cutoff_hz" in fitted:
        table["analog_cutoff_hz"] = round(fitted["analog_cutoff_hz"]["value"], 1)
    if clocked.digital_cutoff_hz is not None:
        table["digital_cutoff_hz"] = round(float(clocked.digital_cutoff_hz), 3)
    if stages:
        table["stages"] = list(table.get("stages", [])) + stages
    lines = [f"{k} = {v['value']:.6g}" + (f" +- {v['uncertainty']:.2g}" if _known(v["uncertainty"])
             else "") + f"  ({v['from']})" for k, v in fitted.items()]  # fmt: skip
    lines += [f"{k}: kept at {base.name}'s value ({why})" for k, why in kept.items()]
    return FitResult(fitted, kept, table, lines)


def _known(value: float | None) -> bool:
    """Whether an uncertainty was determined (not None, not NaN, not zero)."""
    return value is not None and bool(np.isfinite(value)) and value != 0


def profile_toml(result: FitResult) -> str:
    """The fitted profile as a sensor file: provenance as comments, then ``[sensor]``."""
    import tomli_w

    header = [
        "# Sensor profile fitted by `sdt twin fit` (an ordinary sensor file:",
        "#   sdt --sensor-file THIS.toml benchmark / validate-noise / twin check ...)",
    ]
    header += [f"# {line}" for line in result.provenance]
    return "\n".join(header) + "\n" + tomli_w.dumps({"sensor": result.profile})
