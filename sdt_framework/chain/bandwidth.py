"""What a sensor's chain passes, so that every band a figure measures stays inside it.

A figure that reads a band (the NSD band of Fig. 4, the 10-1000 Hz of the
velocity overall) reads what the chain let through only below the chain's
bandwidth: above it the curve is the filter's skirt, noise that the filter
removed or quantisation, and a mean over it says nothing about the part. The
LIS3DH in high-resolution mode at 1344 Hz has a 149 Hz digital low-pass
(ODR/9): the 10-1500 Hz NSD band read 100.9 µg/√Hz against its configured 220
because 80 % of the band lay above 149 Hz.

:func:`passband` gives the chain's bandwidth (the lowest of its mechanical,
analog and digital corners and its output Nyquist) and what sets it;
:meth:`Passband.clip` a band cut to it, and :meth:`Passband.note` the words a
caption says when it cut. The corners are the -3 dB points of the profile's
(X axis) Butterworth stages, as the chain designs them (SPEC section 2).
"""

from __future__ import annotations

from dataclasses import dataclass

from ..specs import SensorSpec

__all__ = ["Passband", "passband"]


@dataclass(frozen=True)
class Passband:
    """The top of the band ``sensor``'s chain passes, and what sets it."""

    sensor: str
    top_hz: float
    limit: str

    def clip(self, band_hz: tuple[float, float]) -> tuple[float, float] | None:
        """``band_hz`` with its top cut to :attr:`top_hz`; None when nothing of it is left."""
        lo, hi = band_hz
        hi = min(hi, self.top_hz)
        return (lo, hi) if hi > lo else None

    def note(self, band_hz: tuple[float, float]) -> str:
        """What a caption says about ``band_hz``: empty when the chain passes all of it."""
        clipped = self.clip(band_hz)
        if clipped == band_hz:
            return ""
        shown = f"{band_hz[0]:g}-{band_hz[1]:g} Hz"
        if clipped is None:
            return f"{shown} lies above {self.limit}"
        return f"{shown} clipped to {clipped[0]:g}-{clipped[1]:.0f} Hz by {self.limit}"


def passband(sensor: SensorSpec, fs: float) -> Passband:
    """The bandwidth of ``sensor``'s chain on a recording at ``fs`` Hz (lowest corner or Nyquist).

    A corner at or above the Nyquist frequency of the rate its stage runs at is
    skipped by the chain (docs/chain.md), and is skipped here too; the
    recording's own Nyquist frequency bounds a chain at the recording's rate.
    """
    sensor = sensor.at_rate(fs)
    out_nyquist = float(sensor.sampling_rate_hz) / 2
    digital_rate = fs if sensor.sampling == "decimate" else 2 * out_nyquist
    limits = [
        (fs / 2, f"the recording's {fs / 2:g} Hz Nyquist frequency"),
        (out_nyquist, f"its {out_nyquist:g} Hz output Nyquist frequency"),
    ]
    for name, cutoff, rate in (
        ("mechanical", sensor.mech_cutoff_hz, fs),
        ("analog", sensor.analog_cutoff_hz, fs),
        ("digital", sensor.digital_cutoff_hz, digital_rate),
    ):
        if cutoff is not None and cutoff < rate / 2:
            limits.append((float(cutoff), f"its {cutoff:.0f} Hz {name} low-pass"))
    top, limit = min(limits, key=lambda item: item[0])
    return Passband(sensor.name, top, limit)
