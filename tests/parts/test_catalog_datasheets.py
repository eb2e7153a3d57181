"""Every catalogue part against the datasheet figures, written here independently of its file.

The table below was typed from the research notes (one per part, read from the
datasheets listed in each part's [documents]), not generated from the TOML
files: ranges and output data rates over all modes, the noise density of the
named mode per axis, and the ADC bits over all modes. A part file that drifts
from its datasheet fails here. Every value of every mode must also carry its
provenance (document, where, basis) or say why it is absent and what stands in.
"""

from __future__ import annotations

import pytest

from sdt_framework.parts import PartSpec, all_modes, resolve, split_name

pytestmark = pytest.mark.catalog
sdt_sensors_catalog = pytest.importorskip(
    "sdt_sensors_catalog", reason="install plugins/sensors-catalog (make does)"
)

ADXL_ODR = {3200, 1600, 800, 400, 200, 100, 50, 25, 12.5, 6.25}
ADXL345_ODR = ADXL_ODR | {3.13, 1.56, 0.78, 0.39, 0.2, 0.1}
ADXL355_ODR = {4000, 2000, 1000, 500, 250, 125, 62.5, 31.25, 15.625, 7.813, 3.906}
KX134_ODR = {0.781, 1.563, 3.125, 6.25, 12.5, 25, 50, 100, 200, 400, 800, 1600, 3200, 6400,
             12800, 25600}  # fmt: skip

#: part -> (ranges g, ODRs Hz, {mode: (x, y, z) noise ug/sqrt(Hz)}, ADC bits over all modes)
DATASHEETS: dict[str, tuple[set[float], set[float], dict[str, tuple[float, ...]], set[int]]] = {
    # ADXL1002: +/-50 g, 25 ug/sqrt(Hz) (EngineerZone 91004); the ADC is the user's
    "adxl1002": ({50}, {3200, 6400, 10000, 12800, 20000, 25600, 51200},
                 {"adxl1002": (25, 25, 25)}, {12, 16, 18, 24}),
    # ADXL313 Rev. D Table 1: 150 X/Y, 250 Z; 10-bit mode or 10..13 bits full resolution
    "adxl313": ({0.5, 1, 2, 4}, ADXL_ODR, {"adxl313": (150, 150, 250)}, {10, 11, 12, 13}),
    # ADXL345 Rev. G p. 33: 290 X/Y, 430 Z
    "adxl345-ds": ({2, 4, 8, 16}, ADXL345_ODR, {"adxl345-ds": (290, 290, 430)},
                   {10, 11, 12, 13}),
    # ADXL355 Rev. D Table 2: 22.5 at +/-2 g, 25 at +/-8 g (4 g: 8 g figure stands in)
    "adxl355": ({2, 4, 8}, ADXL355_ODR,
                {"adxl355[range=2g]": (22.5,) * 3, "adxl355[range=8g]": (25,) * 3}, {20}),
    # ADXL357 Rev. A page 1: 75 all axes; ranges from distributor data; ODR as ADXL355
    "adxl357-ds": ({10, 20, 40}, ADXL355_ODR, {"adxl357-ds": (75,) * 3}, {20}),
    # ADXL372 Rev. C Table 1: 200 g, 12 bits; 3.5 LSB x 100 mg / sqrt(1600 Hz) = 8750
    "adxl372": ({200}, {400, 800, 1600, 3200, 6400}, {"adxl372": (8750,) * 3}, {12}),
    # BMI270 rev 1.5 Table 2: 0.16 mg/sqrt(Hz) at 8 g
    "bmi270": ({2, 4, 8, 16}, {12.5, 25, 50, 100, 200, 400, 800, 1600},
               {"bmi270": (160,) * 3}, {16}),
    # IIM-42352 DS-000442 Table 1: 70 ug/sqrt(Hz); Low-Noise ODRs from 2 kHz
    "iim42352": ({2, 4, 8, 16}, {2000, 4000, 8000, 16000, 32000}, {"iim42352": (70,) * 3}, {16}),
    # IIS3DWB DS12569 Rev 7 Table 3: 75/75/110 three axes, 60/60/80 single axis
    "iis3dwb": ({2, 4, 8, 16}, {26667},
                {"iis3dwb": (75, 75, 110), "iis3dwb[axes=single]": (60, 60, 80)}, {16}),
    # ISM330DHCX DS13012 Rev 7 Table 2: 60 ug/sqrt(Hz) high-performance
    "ism330dhcx": ({2, 4, 8, 16}, {12.5, 26, 52, 104, 208, 416, 833, 1666, 3332, 6667},
                   {"ism330dhcx": (60,) * 3}, {16}),
    # KX134 Specifications Rev 1.0 Table 1: 300 ug/sqrt(Hz)
    "kx134": ({8, 16, 32, 64}, KX134_ODR, {"kx134": (300,) * 3}, {16}),
    # LIS2DW12 DS11811 Rev 9: HP 110 (low-noise off, Table 10), 90 (on, Table 3/11)
    "lis2dw12": ({2, 4, 8, 16}, {12.5, 25, 50, 100, 200, 400, 800, 1600},
                 {"lis2dw12": (110,) * 3, "lis2dw12[low_noise=on]": (90,) * 3}, {14}),
    # LIS3DH DocID17530 Rev 2 Table 4: 220 (HR); 12/10/8 bits HR/normal/LP (Table 10)
    "lis3dh": ({2, 4, 8, 16}, {1, 10, 25, 50, 100, 200, 400, 1344, 1600, 5376},
               {"lis3dh[mode=hr]": (220,) * 3}, {8, 10, 12}),
    # MPU-6050 PS Rev 3.4 Table 6.2: 400 ug/sqrt(Hz); accelerometer at 1 kHz
    "mpu6050": ({2, 4, 8, 16}, {1000}, {"mpu6050": (400,) * 3}, {16}),
}  # fmt: skip

PARTS = {part.name: part for part in sdt_sensors_catalog.load_parts()}


def test_the_catalogue_has_at_least_twelve_parts_and_the_table_covers_them():
    assert len(PARTS) >= 12
    assert set(PARTS) == set(DATASHEETS)


@pytest.mark.parametrize("name", sorted(DATASHEETS))
def test_part_matches_its_datasheet(name):
    ranges, rates, noise, bits = DATASHEETS[name]
    part: PartSpec = PARTS[name]
    sensors = [resolve(part, mode).sensor for mode in all_modes(part)]
    assert {s.full_scale_g for s in sensors} == ranges
    assert {s.sampling_rate_hz for s in sensors} == rates
    assert {s.adc_bits for s in sensors} == bits
    for label, expected in noise.items():
        sensor = resolve(part, split_name(label)[1]).sensor
        assert tuple(sensor.for_axis(a).noise_density_ug_rthz for a in "xyz") == expected


@pytest.mark.parametrize("name", sorted(DATASHEETS))
def test_every_value_of_every_mode_has_its_provenance(name):
    part = PARTS[name]
    for mode in all_modes(part):
        resolved = resolve(part, mode)
        for src in resolved.sources:
            if src.absent:  # what the documents lack, what stands in and why
                assert src.why, (resolved.sensor.name, src.field)
                assert src.value is None or (src.source and src.where)
            elif src.source == "chain model":  # the chain's own filter orders, SPEC section 2,
                # and the paper's sampling model where a part states none (docs/chain.md)
                assert src.field in {"mech_order", "analog_order", "sampling"}
                assert src.field != "sampling" or src.value == "sample-then-filter"
            else:
                assert src.source and src.where and src.basis, (resolved.sensor.name, src.field)
    for key, mode in part.modes.items():
        assert mode.default_why, f"{name}: mode {key} does not say why its default"


def test_fractions_of_the_odr_follow_the_odr():
    adxl355 = PARTS["adxl355"]
    for odr, lpf in ((4000, 1000), (1000, 250), (3.906, 0.9765)):  # Table 44: LPF = ODR/4
        sensor = resolve(adxl355, {"odr": f"{odr:g}"}).sensor
        assert sensor.digital_cutoff_hz == pytest.approx(lpf, rel=1e-3)


def test_a_price_says_currency_quantity_source_and_date():
    priced = {n: p.price for n, p in PARTS.items() if p.price is not None}
    assert priced["adxl345-ds"].amount == 3.92 and priced["adxl345-ds"].currency == "EUR"
    assert priced["iis3dwb"].amount == 13.19
    assert all(p.quantity and p.source and p.date for p in priced.values())
    assert "adxl355" not in priced  # not found: absent, not guessed
