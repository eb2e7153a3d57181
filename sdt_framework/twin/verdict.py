"""What the check concludes about calibration, and why no band could be judged.

Both name the first cause that explains what was seen, before any reading of
the gain or of the motion:

1. **The device's rate is not the part's.** A part runs at its nominal
   output rate or at a power-of-two division of it (an ODR setting), off by a
   few % of clock error. A measured rate off by more than
   :data:`RATE_TOLERANCE` from every such rate (an ADXL345 channel checked as
   an IIS3DWB: 3134 Hz for 26667 Hz) is a different part or a wrong rate
   (timestamps in milliseconds read as seconds, a ``rate_hz`` off 1000-fold):
   nothing measured after it is a calibration.
2. **The twin or the device clips.** The gain at a tone that one of them
   flattens may be the clipping's (a few clipped shock peaks can carry most
   of a record's low-frequency power); a device beyond the part's full scale
   is not that part, or not at that range.
3. Then the static reading (a DC-coupled part at rest reads 1 g), and the
   gain at the dominant tone: **no gain** when no tone is coherent enough to
   read one, the **reference's** disagreement when the device reads gravity
   right and the gain is off, agreement otherwise.

A ``--reference-scale`` (the correction the last case points to) is refused
outside :data:`SCALE_RANGE` before any work (:func:`check_reference_scale`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..errors import SDTError
from ..specs import SensorSpec
from ..units import units_list
from .clipping import Clipping
from .signals import unit_mistake
from .spectra import TONE_FACTOR
from .transfer import Transfer

__all__ = [
    "COHERENT",
    "RATE_TOLERANCE",
    "SCALE_RANGE",
    "STATIC_TOLERANCE",
    "Calibration",
    "RateSetting",
    "calibration",
    "check_reference_scale",
    "no_band",
    "rate_mismatch",
    "rate_setting",
]

#: a --reference-scale outside this range (+-20 dB) is no calibration correction
SCALE_RANGE = (0.1, 10.0)
#: the tone's transfer must be this coherent before its gain is read as a calibration
COHERENT = 0.98
#: a device whose mean vector is within this share of 1 g has a sound static calibration
STATIC_TOLERANCE = 0.05
#: a measured rate this far (share) from the nominal rate and all its power-of-two divisions
#: is not the part's
RATE_TOLERANCE = 0.05


@dataclass(frozen=True)
class RateSetting:
    """A measured output rate against the part's nearest rate setting, ``nominal_hz / 2**k``
    (an ODR setting; ``k`` 0 to 16): an ADXL357 set to 500 Hz is 0.6 % off its setting,
    not 87 % off the profile's 4000 Hz, so the clock error is read against the setting."""

    rate_hz: float
    nominal_hz: float
    k: int

    @property
    def setting_hz(self) -> float:
        """The setting the part runs at, Hz."""
        return self.nominal_hz / 2**self.k

    @property
    def error_pct(self) -> float:
        """The clock error against that setting, %."""
        return 100 * (self.rate_hz / self.setting_hz - 1)

    def __str__(self) -> str:
        """``+0.61 % from 4000``, ``-0.53 % from the 500 Hz setting of 4000``."""
        where = f"the {self.setting_hz:g} Hz setting of {self.nominal_hz:g}" if self.k else (
            f"{self.nominal_hz:g}")  # fmt: skip
        return f"{self.error_pct:+.2f} % from {where}"


def rate_setting(rate_hz: float, nominal_hz: object) -> RateSetting | None:
    """``rate_hz`` against the nearest setting of ``nominal_hz``; None when either is not a
    positive number (a profile without a nominal rate)."""
    if not (isinstance(nominal_hz, int | float) and rate_hz > 0 and nominal_hz > 0):
        return None
    if not (math.isfinite(rate_hz) and math.isfinite(nominal_hz)):
        return None
    k = int(min(max(round(math.log2(nominal_hz / rate_hz)), 0), 16))
    return RateSetting(float(rate_hz), float(nominal_hz), k)


def rate_mismatch(sensor: SensorSpec, rate_hz: float) -> str | None:
    """Why ``rate_hz`` cannot be ``sensor``'s output rate, or None when it can be."""
    nominal = sensor.sampling_rate_hz
    if not isinstance(nominal, float):
        return None
    setting = rate_setting(rate_hz, nominal)
    if setting is None or abs(rate_hz / setting.setting_hz - 1) <= RATE_TOLERANCE:
        return None
    times = nominal / rate_hz
    how = f"{times:.3g} times slower" if times > 1 else f"{1 / times:.3g} times faster"
    return (
        f"the device runs at {rate_hz:.4g} Hz, {how} than {sensor.name}'s {nominal:g} Hz and "
        f"off every power-of-two setting of it by more than {100 * RATE_TOLERANCE:g} %: "
        f"another part (check --device-channel), or {unit_mistake()}"
    )


def _clipping(clipped: Clipping, sensor: SensorSpec, device: np.ndarray) -> str | None:
    """The clipping that explains a gain, or None."""
    full = sensor.full_scale_g
    if full is None:
        return None
    found = []
    peak = float(np.abs(device).max()) if device.size else 0.0
    beyond = peak > 1.01 * full
    if beyond:
        found.append(
            f"the device reads up to {peak:.3g} g, beyond {sensor.name}'s +-{full:g} g full "
            f"scale: it is not that part at that range"
        )
    sides = {"twin": clipped.twin_clipping, "device": clipped.device_clipping}
    for side in ("twin",) if beyond else ("twin", "device"):
        c = sides[side]
        if c.count:
            found.append(
                f"the {side} clips ({c.count} samples, {100 * c.share:.2g} % of them, "
                f"at +-{full:g} g)"
            )
    if not found:
        return None
    return "; ".join(found) + ": the gain at the tone may be the clipping's, not a calibration"


@dataclass(frozen=True)
class Calibration:
    """The device's static reading (|mean vector|, g) and whether it is within
    :data:`STATIC_TOLERANCE` of 1 g, the gain (device / twin) at the dominant tone and its
    frequency (None: no tone), whether the gain can be the reference's, and the verdict."""

    static_g: float
    static_sound: bool
    tone_gain: float | None
    tone_hz: float | None
    reference_off: bool
    verdict: str


def calibration(device: np.ndarray, transfer: Mapping[tuple[int, int], Transfer], main: int,
                clipped: Clipping, sensor: SensorSpec, rate_hz: float,
                spectrum: tuple[np.ndarray, np.ndarray]) -> Calibration:  # fmt: skip
    """The device's static reading (|mean vector|, g), the gain at the dominant tone, and the
    verdict (module docstring); ``reference_off`` only when the gain can be the reference's.

    ``spectrum`` is the device's (frequencies, density) on the main axis: a gain is read
    only at a *tone* (a bin :data:`.spectra.TONE_FACTOR` times the median density or more).
    In broadband motion every bin is coherent and none is a tone; the gain there is the
    estimator's (twin noise biases it low), not a calibration.
    """
    freqs, density = spectrum
    tonal = density >= TONE_FACTOR * np.median(density[1:])
    static = float(np.linalg.norm(device.mean(axis=1)))
    tone = max(
        (
            v
            for (i, _), v in transfer.items()
            if i == main
            and v.coherence >= COHERENT
            and tonal[int(np.argmin(np.abs(freqs - v.at_hz)))]
        ),
        key=lambda v: v.coherence,
        default=None,
    )
    gain = None if tone is None else float(10 ** (tone.gain_db / 20))
    sound = abs(static - 1.0) <= STATIC_TOLERANCE
    off = gain is not None and abs(gain - 1.0) > STATIC_TOLERANCE
    causes = [c for c in (rate_mismatch(sensor, rate_hz), _clipping(clipped, sensor, device)) if c]
    if causes:
        verdict, off = "; and ".join(causes), False
    elif not sound:
        verdict = "the device does not read 1 g at rest (AC-coupled, or its calibration is off)"
    elif gain is None:
        verdict = (
            f"the device reads gravity right; no gain could be compared (no tone on the "
            f"main axis coherent to {COHERENT:g} or more between twin and device)"
        )
    elif off:
        verdict = "the device reads gravity right: the gain disagreement is the reference's"
    else:
        verdict = "the device reads gravity right and agrees with the reference in gain"
    return Calibration(
        static_g=static,
        static_sound=sound,
        tone_gain=gain,
        tone_hz=None if tone is None else tone.at_hz,
        reference_off=bool(sound and off),
        verdict=verdict,
    )


def no_band(name: str, sensor: SensorSpec, rate_hz: float, limit: float, bands: int,
            margin_db: float) -> str:  # fmt: skip
    """The refusal when no band can be judged, naming the first cause: a device rate that
    leaves no band or is not the part's, else a reference with no motion above its floor."""
    mismatch = rate_mismatch(sensor, rate_hz)
    if not bands:
        nominal = sensor.sampling_rate_hz
        ratio = (
            f", {nominal / rate_hz:.4g} times below {sensor.name}'s {nominal:g} Hz"
            if isinstance(nominal, float) and rate_hz > 0
            else ""
        )
        return (
            f"{name}: no band can be judged: the device's rate ({rate_hz:.4g} Hz{ratio}) "
            f"leaves no third octave between 10 Hz and its Nyquist; a rate mismatch, not a "
            f"recording at rest: check the pair's time column (seconds, not milliseconds) "
            f"or rate_hz"
        )
    if mismatch:
        return f"{name}: no band can be judged: {mismatch}"
    return (
        f"{name}: no band can be judged: on every axis the reference stays within "
        f"{margin_db:g} dB of its own floor (read from its quietest seconds) below its band "
        f"limit ({limit:.0f} Hz), so it carries no motion to compare (a recording at rest? "
        f"`sdt validate-noise --recording` checks a noise floor)"
    )


def check_reference_scale(factor: float) -> None:
    """Refuse a ``--reference-scale`` outside :data:`SCALE_RANGE`: it corrects a reference's
    calibration, which is never off by 20 dB; a factor beyond that is a typo (1626 for
    1.626) or a unit conversion, and would give a confident wrong check (a twin clipping on
    a reference 1000 times too strong, or a reference below the smallest float)."""
    lo, hi = SCALE_RANGE
    if not (np.isfinite(factor) and lo <= factor <= hi):
        raise SDTError(
            f"--reference-scale {factor:g}: outside the plausible {lo:g}-{hi:g}; it corrects "
            f"the reference's calibration (the check's 'calibration' line gives the factor, "
            f"e.g. 1.626), which is never off by 20 dB; for other units give the pair "
            f"file's units ({units_list()})"
        )
