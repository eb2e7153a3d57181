"""ADXL357 profile: a high-end low-noise MEMS accelerometer (paper Table 1, profile 2)."""

from __future__ import annotations

from sdt_framework import SensorSpec, hookimpl
from sdt_framework.specs.supply import Supply, SupplyFigure

_DS = "Analog Devices ADXL356/ADXL357 Data Sheet, Rev. A"
_LOW_POWER = "page 1, Features: Low power, VSUPPLY (LDO regulator enabled)"
#: Supply of the ADXL357 (one figure for every ODR: the Features list gives no current per rate).
SUPPLY = Supply(
    measure_ua=SupplyFigure(
        value=200,
        doc=_DS,
        where=_LOW_POWER,
        printed="ADXL357 in measurement mode: 200 μA",
        basis="typical",
    ),
    standby_ua=SupplyFigure(
        value=21,
        doc=_DS,
        where=_LOW_POWER,
        printed="ADXL356/ADXL357 in standby mode: 21 μA",
        basis="typical",
    ),
    turn_on_ms=SupplyFigure(
        absent="only the Features page of the datasheet was read; it gives no turn-on time"
    ),
    mode="odr=4000",
)

ADXL357 = SensorSpec(
    name="adxl357",
    description="Analog Devices ADXL357, +/-40 g, 20-bit sigma-delta, 4000 Hz output data rate",
    source="Analog Devices ADXL356/ADXL357 datasheet Rev. A; paper Table 1 (profile 2)",
    sampling_rate_hz=4000,
    full_scale_g=40,
    adc_bits=20,
    noise_density_ug_rthz=90,
    mech_cutoff_hz=5500,
    mech_order=2,
    analog_cutoff_hz=1500,
    analog_order=1,
    digital_cutoff_hz=1000,
    digital_order=8,
    supply=SUPPLY,
    # Unit-to-unit spread, used only by `sdt benchmark --units N` (not hashed, nominal unchanged):
    # sensitivity 47104/51200/55296 LSB/g min/typ/max at +-10 g (+-8 %), the datasheet table as
    # quoted and confirmed by ADI on EngineerZone (ez.analog.com, q-a 104360); secondary source.
    tolerances={"scale.error_pct": {"distribution": "uniform", "spread": 8.0}},
)


@hookimpl
def register_sensors(register):
    """Register the ADXL357 profile."""
    register(ADXL357)
