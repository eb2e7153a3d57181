"""ADXL345 profile: a mid-range MEMS accelerometer (paper Table 1, profile 1)."""

from __future__ import annotations

from sdt_framework import SensorSpec, hookimpl
from sdt_framework.specs.supply import Supply, SupplyFigure

_DS = "Analog Devices ADXL345 Data Sheet"
#: Supply at the profile's 3200 Hz, normal power mode (the catalogue part adxl345-ds has every ODR).
SUPPLY = Supply(
    measure_ua=SupplyFigure(
        value=140,
        doc=f"{_DS}, Rev. E",
        where="Table 7, Typical Current Consumption vs. Data Rate (VS = 2.5 V), row ODR 3200 Hz",
        printed="3200 1600 1111 140",
        basis="typical",
        note="Row: ODR (Hz), bandwidth (Hz), rate code, IDD (µA).",
    ),
    standby_ua=SupplyFigure(
        value=0.1,
        doc=f"{_DS}, Rev. D",
        where="page 1, Features",
        printed="0.1 µA in standby mode at VS = 2.5 V (typical)",
        basis="typical",
    ),
    turn_on_ms=SupplyFigure(
        absent="the Table 1 turn-on and wake-up time row was not in the datasheet pages read"
    ),
    mode="odr=3200",
)

ADXL345 = SensorSpec(
    name="adxl345",
    description="Analog Devices ADXL345, +/-16 g, 13-bit SAR, 3200 Hz output data rate",
    source="Analog Devices ADXL345 datasheet Rev. G; paper Table 1 (profile 1)",
    sampling_rate_hz=3200,
    full_scale_g=16,
    adc_bits=13,
    noise_density_ug_rthz=290,
    mech_cutoff_hz=7000,
    mech_order=2,
    analog_cutoff_hz=1600,
    analog_order=1,
    digital_cutoff_hz=1599,
    digital_order=1,
    # Unit-to-unit spread, used only by `sdt benchmark --units N` (not hashed, nominal unchanged):
    # Rev. G Table 1: sensitivity 230/256/282 LSB/g min/typ/max (+-10.2 %, guaranteed limits);
    # 0 g output deviation from ideal, X/Y, +-35 mg typ (typ = mean +- 1 sigma, footnote 1).
    supply=SUPPLY,
    tolerances={
        "scale.error_pct": {"distribution": "uniform", "spread": 10.2},
        "offset.offset_mg": {"distribution": "normal", "spread": 35.0},
    },
)


@hookimpl
def register_sensors(register):
    """Register the ADXL345 profile."""
    register(ADXL345)
