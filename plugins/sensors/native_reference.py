"""Rate-following reference: the recording as it is, at whatever rate it was made.

The default reference for data that is not at 20 kHz (SPEC section 9): a
12 kHz, 25.6 kHz or 51.2 kHz recording is its own reference, so the default
sensor set runs on it. Its rate is the recording's ('native'), it has no
filter stage, injects no noise (the recording carries its chain's own) and
does not requantise (the recording is already digitised), so its output is the
input, bit for bit, and deterministic.
"""

from __future__ import annotations

from sdt_framework import SensorSpec, hookimpl

NATIVE_REFERENCE = SensorSpec(
    name="native-reference",
    description="Reference: the recording as is, at its own rate (identity chain)",
    source="docs/sensors.md: the reference follows the data",
    sampling_rate_hz="native",
    full_scale_g=None,
    adc_bits=None,
    noise_density_ug_rthz=0,
    inject_noise=False,
    requantise=False,
    mech_cutoff_hz=None,
    analog_cutoff_hz=None,
)


@hookimpl
def register_sensors(register):
    """Register the rate-following reference."""
    register(NATIVE_REFERENCE)
