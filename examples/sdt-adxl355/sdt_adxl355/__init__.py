"""ADXL355 sensor profile: an example of a third-party sdt-framework plugin.

Values from the Analog Devices ADXL354/ADXL355 datasheet (Rev. D): +/-8 g
range, 20-bit output, 25 ug/sqrt(Hz) noise density, 4000 Hz output data rate
with the on-chip decimation filter at ODR/4. The mechanical and anti-alias
stages follow the ADXL357 profile of the same family (paper Table 1).

The sensor is named ``adxl355-example``: the part ``adxl355`` (with its modes
and per-value provenance) comes from the sdt-sensors-catalog distribution, and
no two installed distributions may register the same name.
"""

from __future__ import annotations

from sdt_framework import SensorSpec, hookimpl

ADXL355 = SensorSpec(
    name="adxl355-example",
    description="Analog Devices ADXL355, +/-8 g, 20-bit sigma-delta, 4000 Hz output data rate",
    source="Analog Devices ADXL354/ADXL355 datasheet Rev. D; front end as the ADXL357 profile",
    sampling_rate_hz=4000,
    full_scale_g=8,
    adc_bits=20,
    noise_density_ug_rthz=25,
    mech_cutoff_hz=5500,
    analog_cutoff_hz=1500,
    digital_cutoff_hz=1000,
    digital_order=8,
)


@hookimpl
def register_sensors(register):
    """Register the ADXL355 profile."""
    register(ADXL355)
