"""LoRa time on air against values published by independent calculators.

Every expected value below was computed by someone else with the SX127x /
AN1200.13 formula, under the stated conditions, and is quoted from its source.
"""

from __future__ import annotations

import pytest

from sdt_framework import SDTError
from sdt_framework.edge import (
    OVERHEAD_BYTES,
    low_data_rate_optimize,
    payload_symbols,
    symbol_time_s,
    time_on_air_s,
)

BW125 = 125e3


def test_ten_byte_lorawan_payload_at_sf7_is_61_7_ms():
    # Semtech's LoRa calculator / TTN airtime calculator: 10 application bytes,
    # SF7/125 kHz, preamble 8, CR 4/5, explicit header, CRC on -> 61.7 ms. The
    # calculators count the 13 LoRaWAN bytes, so the PHY payload is 23 bytes.
    assert time_on_air_s(10 + OVERHEAD_BYTES, 7, BW125) == pytest.approx(61.696e-3, abs=1e-9)
    assert round(time_on_air_s(23, 7, BW125) * 1e3, 1) == 61.7


@pytest.mark.parametrize(
    ("sf", "ldro", "expected_ms", "preamble_ms"),
    [(7, False, 41.216, 12.544), (11, True, 577.536, 200.704)],
)
def test_rfwireless_world_examples(sf, ldro, expected_ms, preamble_ms):
    # rfwireless-world.com "LoRaWAN Airtime calculator", examples 1 and 2:
    # PL = 10 bytes, CR 4/5, BW 125 kHz, 8 preamble symbols, header present.
    assert time_on_air_s(10, sf, BW125, low_data_rate=ldro) == pytest.approx(
        expected_ms * 1e-3, abs=1e-9
    )
    assert (8 + 4.25) * symbol_time_s(sf, BW125) == pytest.approx(preamble_ms * 1e-3)


@pytest.mark.parametrize(
    ("sf", "expected_ms"),
    [(7, 82.176), (8, 143.872), (9, 267.264), (10, 493.568), (11, 1069.056), (12, 1974.272)],
)
def test_ttn_airtime_spreadsheet_24_byte_application_payload(sf, expected_ms):
    # TTN community airtime spreadsheet (docs.google.com/spreadsheets/d/1eL1nHxMidIcIdDE...),
    # formulas from AN1200.13: 24 application bytes + 13 LoRaWAN header, explicit
    # header, low-DR optimisation "auto" (SF11-12 at 125 kHz), CR 4/5, preamble 8.
    assert time_on_air_s(24 + 13, sf, BW125) == pytest.approx(expected_ms * 1e-3, abs=1e-9)


def test_an1200_spreadsheet_intermediate_values():
    # docs.google.com/spreadsheets/d/1voGAtQAjC1qBmaVuP1ApNKs1ekgUjavHuVQIXyYSvNc:
    # 13 bytes, SF9, explicit header, low-DR optimise no, CR 4/5, preamble 8, 125 kHz.
    assert symbol_time_s(9, BW125) == pytest.approx(4.096e-3)
    assert payload_symbols(13, 9, BW125, low_data_rate=False) == 28
    assert time_on_air_s(13, 9, BW125, low_data_rate=False) == pytest.approx(164.864e-3)


def test_ttn_console_value_for_4_bytes_at_sf12():
    # TTN forum "About Duty Cycle and sub-bands": 4 bytes + 13 header at SF12BW125
    # "gives me a time in air of 1318.9ms in the TTN console".
    assert round(time_on_air_s(4 + 13, 12, BW125) * 1e3, 1) == 1318.9


def test_low_data_rate_optimisation_switches_on_above_16_ms_symbols():
    # SX1276 datasheet: mandated when the symbol duration exceeds 16 ms
    assert [low_data_rate_optimize(sf, BW125) for sf in range(7, 13)] == [False] * 4 + [True] * 2
    assert low_data_rate_optimize(12, 250e3)  # 16.384 ms at 250 kHz: on
    assert not low_data_rate_optimize(11, 250e3)  # 8.192 ms


def test_each_option_lengthens_or_shortens_the_packet_as_the_formula_says():
    base = payload_symbols(20, 9, BW125)
    assert payload_symbols(20, 9, BW125, crc=False) <= base
    assert payload_symbols(20, 9, BW125, explicit_header=False) <= base
    assert payload_symbols(20, 9, BW125, coding_rate=4) > base
    longer = time_on_air_s(20, 9, BW125, preamble_symbols=12)
    assert longer - time_on_air_s(20, 9, BW125) == pytest.approx(4 * symbol_time_s(9, BW125))


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"sf": 13}, "spreading factor"),
        ({"bandwidth_hz": 0.0}, "bandwidth"),
        ({"payload_bytes": 256}, "0..255 bytes"),
        ({"coding_rate": 5}, "coding rate"),
        ({"preamble_symbols": -1}, "preamble"),
    ],
)
def test_bad_radio_settings_are_one_clear_error(kwargs, message):
    args = {"payload_bytes": 10, "sf": 7, "bandwidth_hz": BW125, **kwargs}
    with pytest.raises(SDTError, match=message):
        time_on_air_s(**args)
