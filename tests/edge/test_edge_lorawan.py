"""LoRaWAN framing and the regional payload limits, against the published tables."""

from __future__ import annotations

import pytest

from sdt_framework import SDTError, UnknownNameError
from sdt_framework.edge import OVERHEAD_BYTES, phy_payload_bytes, region, time_on_air_s


def test_frame_overhead_is_mhdr_fhdr_fport_mic():
    # TS001-1.0.4 section 4: MHDR 1 + (DevAddr 4 + FCtrl 1 + FCnt 2) + FPort 1 + MIC 4
    assert OVERHEAD_BYTES == 1 + (4 + 1 + 2) + 1 + 4 == 13
    assert phy_payload_bytes(96) == 109
    assert phy_payload_bytes(96, fopts_bytes=15) == 124
    with pytest.raises(SDTError, match="FOpts"):
        phy_payload_bytes(10, fopts_bytes=16)


def test_eu868_data_rates_and_payload_limits():
    eu = region("EU868")
    assert [r.label for r in eu.data_rates] == [
        "SF12/125 kHz",
        "SF11/125 kHz",
        "SF10/125 kHz",
        "SF9/125 kHz",
        "SF8/125 kHz",
        "SF7/125 kHz",
        "SF7/250 kHz",
    ]
    # TTN EU863-870 page (RP002-1.0.2), repeater compatible: N for DR0..DR6
    assert [r.max_app_payload() for r in eu.data_rates] == [51, 51, 51, 115, 222, 222, 222]
    # not repeater compatible: LoRaMac-node MaxPayloadOfDatarateEU868 {51,51,51,115,242,...}
    no_rep = [r.max_app_payload(repeater=False) for r in eu.data_rates]
    assert no_rep == [51, 51, 51, 115, 242, 242, 242]
    assert eu.duty_cycle == 0.01 and eu.preamble_symbols == 8


def test_us915_data_rates_and_payload_limits():
    us = region("us915")  # case-insensitive
    assert [r.label for r in us.data_rates] == [
        "SF10/125 kHz",
        "SF9/125 kHz",
        "SF8/125 kHz",
        "SF7/125 kHz",
        "SF8/500 kHz",
    ]
    # TTN US902-928 page (repeater compatible) and Regional Parameters v1.0.3revA Table 16
    assert [r.max_app_payload() for r in us.data_rates] == [11, 53, 125, 222, 222]
    assert [r.max_app_payload(repeater=False) for r in us.data_rates] == [11, 53, 125, 242, 242]
    assert us.duty_cycle is None
    assert [r.dwell_time_s for r in us.data_rates] == [0.4, 0.4, 0.4, 0.4, None]


def test_us915_dr0_limit_is_the_400_ms_dwell_time():
    # The 11-byte limit at SF10/125 kHz is what keeps an uplink under 400 ms:
    # 24-byte PHY payload -> 12.25 + 33 symbols of 8.192 ms = 370.688 ms;
    # one more byte -> 12.25 + 38 symbols = 411.648 ms.
    dr0 = region("US915").data_rates[0]
    at_limit = time_on_air_s(phy_payload_bytes(11), dr0.sf, dr0.bandwidth_hz)
    beyond = time_on_air_s(phy_payload_bytes(12), dr0.sf, dr0.bandwidth_hz)
    assert at_limit == pytest.approx(0.370688) and at_limit <= dr0.dwell_time_s
    assert beyond == pytest.approx(0.411648) and beyond > dr0.dwell_time_s


def test_largest_eu868_uplink_fits_the_sx127x_packet_engine():
    for rate in region("EU868").data_rates:
        assert phy_payload_bytes(rate.max_app_payload(repeater=False)) <= 255


def test_unknown_region_lists_the_known_ones():
    with pytest.raises(UnknownNameError, match="EU868, US915"):
        region("AS923")


def test_the_protocol_figures_are_data_with_their_sources():
    """lorawan.toml holds the frame, the regional plans and the receive windows, each sourced;
    the node's RX2 rates are LoRaMac-node's EU868 DR_0 (SF12/125 kHz) and US915 DR_8
    (SF12/500 kHz), its receive window the 8-symbol preamble."""
    from sdt_framework.edge import node_defaults
    from sdt_framework.edge.lorawan import DATA

    assert "TS001-1.0.4" in DATA.frame.source
    assert {r.name: "Regional Parameters v1.0.3revA" in r.source for r in DATA.region} == {
        "EU868": True,
        "US915": True,
    }
    assert all("LoRaMac-node" in r.rx2_source for r in DATA.region)
    assert node_defaults.RX2_MODULATION == {"EU868": (12, 125e3), "US915": (12, 500e3)}
    assert node_defaults.RX_SYMBOLS == region("EU868").preamble_symbols == 8
