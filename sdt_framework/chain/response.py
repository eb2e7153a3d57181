"""What a sensor's chain does to content in a frequency band: passed, attenuated or aliased.

The chain knows both numbers a reader of a spectrum needs: the output rate
(so where content above its Nyquist frequency lands, |f - k F_target|) and
the gain on the way there. In the paper's model (``sampling =
"sample-then-filter"``) content above the output Nyquist reaches the sampler
through the mechanical and analog stages only, folds, and then meets the
digital low-pass at its folded frequency. A decimating part
(``sampling = "decimate"``) meets its decimation low-pass at the input rate
first, so the same content arrives attenuated by that filter's stopband.

:func:`band_fate` answers for one band (a bearing resonance an envelope
demodulates, a band a figure measures); :func:`chain_gain` gives the numbers
line by line. Both use the profile's own (X axis) corners; pass
``sensor.for_axis(a)`` for another axis. Left out, and small where they are
left out: plugin stages (none of them filters), and the sampler's linear
interpolation (its own roll-off, sinc^2(f / F_ref), is under 0.1 dB below
1 kHz from a 20 kHz recording).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..specs import SensorSpec
from .filters import design_lowpass, lowpass_gain

__all__ = ["BandFate", "band_fate", "chain_gain"]

#: a fold at least this far down (dB) is "attenuated": 1 % of the amplitude
REJECT_DB = 40.0
#: an in-band band whose best line is within this of unity gain (dB) is "passed"
PASS_DB = 3.0


def chain_gain(
    sensor: SensorSpec, fs: float, freqs_hz: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Gain of ``sensor``'s chain (from a recording at ``fs`` Hz) and where each line lands.

    Returns ``(gain, out_hz)``: the amplitude gain from the input line at each of
    ``freqs_hz`` to the output, and the output frequency it appears at (itself
    below the output Nyquist, |f - k F_target| above it).
    """
    sensor = sensor.at_rate(fs)
    f = np.asarray(freqs_hz, dtype=np.float64)
    target = float(sensor.sampling_rate_hz)
    gain = np.ones_like(f)
    for order, cutoff in (
        (sensor.mech_order, sensor.mech_cutoff_hz),
        (sensor.analog_order, sensor.analog_cutoff_hz),
    ):
        if cutoff is not None:
            gain *= lowpass_gain(design_lowpass(order, cutoff, fs), f, fs)
    out = f if target == fs else np.abs(f - np.round(f / target) * target)
    if sensor.digital_cutoff_hz is not None and sensor.digital_order is not None:
        decimate = sensor.sampling == "decimate"
        rate, at = (fs, f) if decimate else (target, out)
        gain *= lowpass_gain(
            design_lowpass(sensor.digital_order, sensor.digital_cutoff_hz, rate), at, rate
        )
    return gain, out


@dataclass(frozen=True)
class BandFate:
    """What reaches the output of content in ``band_hz``.

    ``kind``: "aliased" when some of the band lies above the output Nyquist
    and arrives less than :data:`REJECT_DB` down, folded to ``folded_hz``;
    "passed" when it lies below the Nyquist and its best line is within
    :data:`PASS_DB` of unity gain; "attenuated" otherwise. ``gain_db`` is the
    largest gain over the band's lines (over its part above the Nyquist when
    aliased).
    """

    band_hz: tuple[float, float]
    kind: Literal["passed", "attenuated", "aliased"]
    gain_db: float
    nyquist_hz: float
    folded_hz: tuple[float, float] | None
    sampling: str

    def describe(self) -> str:
        """One line for a caption or a table note."""
        lo, hi = self.band_hz
        text = f"{lo:g}-{hi:g} Hz {self.kind} ({self.gain_db:+.1f} dB"
        if self.folded_hz is not None:
            text += f", folded to {self.folded_hz[0]:.0f}-{self.folded_hz[1]:.0f} Hz"
        return f"{text}; output Nyquist {self.nyquist_hz:g} Hz, {self.sampling})"


def band_fate(
    sensor: SensorSpec,
    fs: float,
    band_hz: tuple[float, float],
    *,
    reject_db: float = REJECT_DB,
    points: int = 512,
) -> BandFate:
    """Whether content in ``band_hz`` reaches ``sensor``'s output passed, attenuated or aliased.

    ``fs`` is the rate of the recording the chain runs on (its filters are
    designed there); the band must lie within (0, fs / 2]. The band is read
    on ``points`` evenly spaced lines, its edges included.
    """
    lo, hi = (float(v) for v in band_hz)
    if not (0 < lo < hi <= fs / 2):
        raise ValueError(
            f"band {lo:g}-{hi:g} Hz: give 0 < low < high <= {fs / 2:g} Hz "
            f"(the Nyquist frequency of the {fs:g} Hz recording)"
        )
    sensor = sensor.at_rate(fs)
    nyquist = float(sensor.sampling_rate_hz) / 2
    f = np.linspace(lo, hi, max(2, int(points)))
    gain, out = chain_gain(sensor, fs, f)
    with np.errstate(divide="ignore"):
        db = 20 * np.log10(gain)
    above = f > nyquist
    folded = None
    if above.any() and db[above].max() > -reject_db:
        kind, peak = "aliased", float(db[above].max())
        folded = (float(out[above].min()), float(out[above].max()))
    elif not above.any() and db.max() >= -PASS_DB:
        kind, peak = "passed", float(db.max())
    else:
        kind, peak = "attenuated", float(db.max())
    return BandFate((lo, hi), kind, peak, nyquist, folded, sensor.sampling)
