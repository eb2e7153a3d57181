"""Whether a recording is fast enough to simulate a sensor from it.

The chain only lowers the rate (SPEC section 2), and what a sensor aliases
into its band must be in the recording. So a sensor is not simulable from a
recording at ``fs`` Hz when

- its output data rate is above ``fs``; or
- it resamples (rate below ``fs``) and the band that reaches its sampler,
  bounded by the lowest of its mechanical and analog corners, reaches the
  recording's Nyquist frequency ``fs / 2`` or beyond: the content it would
  alias from there is not in the recording (a stage without a corner does not
  bound the band; with neither, the band is unbounded).

A sensor at exactly the recording's rate does not resample, so nothing
aliases: it is simulable (the reference chains). The check reads the
profile's own (X axis) corners; check ``sensor.for_axis(a)`` for another axis.
"""

from __future__ import annotations

from ..specs import SensorSpec

__all__ = ["simulation_problem"]


def simulation_problem(sensor: SensorSpec, fs: float) -> str | None:
    """Why ``sensor`` cannot be simulated from a recording at ``fs`` Hz, or None if it can."""
    target = float(sensor.at_rate(fs).sampling_rate_hz)
    if target > fs:
        return f"sensor {sensor.name!r} samples at {target:g} Hz, above the data's {fs:g} Hz"
    if target == fs:
        return None
    corners = [c for c in (sensor.mech_cutoff_hz, sensor.analog_cutoff_hz) if c is not None]
    band = min(corners) if corners else None
    if band is None:
        return (
            f"sensor {sensor.name!r} has no mechanical or analog corner: what it would alias "
            f"from above the data's Nyquist {fs / 2:g} Hz is not in the recording"
        )
    if band >= fs / 2:
        return (
            f"sensor {sensor.name!r} passes up to {band:g} Hz to its sampler, at or above the "
            f"data's Nyquist {fs / 2:g} Hz: what it would alias from there is not in the recording"
        )
    return None
