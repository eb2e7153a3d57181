"""LoRaWAN framing and the regional data-rate plans EU868 and US915.

The figures are data, ``lorawan.toml`` beside this module, each table with its
source: the frame overhead (LoRa Alliance, *TS001-1.0.4 LoRaWAN L2 1.0.4
Specification*, section 4, Tables 2 and 6)::

    PHYPayload = MHDR (1) | MACPayload | MIC (4)
    MACPayload = FHDR | FPort (1) | FRMPayload
    FHDR       = DevAddr (4) | FCtrl (1) | FCnt (2) | FOpts (0..15)

so an uplink carrying application bytes on a port, with no MAC commands
piggy-backed in FOpts, costs 1 + 7 + 1 + 4 = 13 bytes on top of them.

Maximum payload per data rate: M is the largest MACPayload, N = M - 8 the
largest application payload when FOpts is empty (LoRaWAN Regional Parameters:
"the maximum application payload length in the absence of the optional FOpt
control field (N)"). Two tables exist per region: repeater compatible (the
default here, the conservative one) and not repeater compatible.

- EU868: LoRaWAN Regional Parameters v1.0.3revA (LoRa Alliance, 2018),
  section 2.2 (default channels, duty cycle < 1 %, Table 3; preamble 8 symbols,
  Table 2), and the EU863-870 maximum payload size tables as published by The
  Things Network's regional-parameters page (based on RP002-1.0.2):
  M = 59, 59, 59, 123, 230, 230, 230 for DR0..DR6 (repeater compatible);
  250 instead of 230 when not repeater compatible (same values as the EU433
  Tables 31-32 of v1.0.3revA and LoRaMac-node's ``MaxPayloadOfDatarateEU868``).
- US915: the same v1.0.3revA, Table 16 "US902-928 maximum payload size (not
  repeater compatible)" (M = 19, 61, 133, 250, 250 for DR0..DR4) and the repeater
  compatible table (230 for DR3, DR4); no duty cycle but a 400 ms dwell time on
  the 125 kHz channels (FCC part 15, as summarised by TTN's US902-928 page).

DR7 of EU868 (FSK) and the LR-FHSS data rates are not LoRa and are left out.
"""

from __future__ import annotations

from dataclasses import dataclass
from numbers import Integral

from ..errors import SDTError, UnknownNameError, shown
from .sourced import DataModel, read_data

__all__ = [
    "FHDR_BYTES",
    "FPORT_BYTES",
    "MHDR_BYTES",
    "MIC_BYTES",
    "OVERHEAD_BYTES",
    "REGIONS",
    "DataRate",
    "Region",
    "phy_payload_bytes",
    "region",
]


class _Frame(DataModel):
    source: str
    mhdr_bytes: int
    fhdr_bytes: int
    fport_bytes: int
    mic_bytes: int


class _Window(DataModel):
    symbols: int
    source: str


class _Region(DataModel):
    name: str
    duty_cycle: float | None = None
    preamble_symbols: int
    dwell_time_s: float | None = None
    data_rates: tuple[tuple[int, float, int, int], ...]
    source: str
    rx2_sf: int
    rx2_bandwidth_hz: float
    rx2_source: str


class _LorawanFile(DataModel):
    frame: _Frame
    receive_window: _Window
    region: tuple[_Region, ...]


#: lorawan.toml, every table with its source
DATA = read_data("lorawan.toml", _LorawanFile)
MHDR_BYTES = DATA.frame.mhdr_bytes
FHDR_BYTES = DATA.frame.fhdr_bytes  # DevAddr 4 + FCtrl 1 + FCnt 2, FOpts empty
FPORT_BYTES = DATA.frame.fport_bytes
MIC_BYTES = DATA.frame.mic_bytes
#: LoRaWAN bytes around the application payload of an uplink without FOpts
OVERHEAD_BYTES = MHDR_BYTES + FHDR_BYTES + FPORT_BYTES + MIC_BYTES
#: MACPayload bytes that are not application payload (FHDR + FPort): N = M - 8
_MAC_OVERHEAD = FHDR_BYTES + FPORT_BYTES


def phy_payload_bytes(app_bytes: int, fopts_bytes: int = 0) -> int:
    """PHY payload of a LoRaWAN uplink carrying ``app_bytes`` of application data.

    ``app_bytes + 13`` plus any FOpts bytes (0..15) carrying MAC commands.
    """
    if not (isinstance(app_bytes, Integral) and app_bytes >= 0):
        raise SDTError(
            f"application payload must be a whole number of bytes, got {shown(app_bytes)}"
        )
    if not (isinstance(fopts_bytes, Integral) and 0 <= fopts_bytes <= 15):
        raise SDTError(f"FOpts holds 0..15 bytes, got {shown(fopts_bytes)}")
    return app_bytes + OVERHEAD_BYTES + fopts_bytes


@dataclass(frozen=True)
class DataRate:
    """One uplink data rate of a regional plan.

    Attributes
    ----------
    index
        DR number in the regional plan.
    sf, bandwidth_hz
        LoRa spreading factor and bandwidth, Hz.
    max_mac_payload, max_mac_payload_no_repeater
        Largest MACPayload M, bytes, in the repeater-compatible and the
        not-repeater-compatible table.
    dwell_time_s
        Longest allowed time on air per transmission, s (None: no limit).
    """

    index: int
    sf: int
    bandwidth_hz: float
    max_mac_payload: int
    max_mac_payload_no_repeater: int
    dwell_time_s: float | None = None

    @property
    def name(self) -> str:
        """``"DR3"``."""
        return f"DR{self.index}"

    @property
    def label(self) -> str:
        """``"SF9/125 kHz"``."""
        return f"SF{self.sf}/{self.bandwidth_hz / 1e3:g} kHz"

    def max_app_payload(self, *, repeater: bool = True) -> int:
        """Largest application payload N = M - 8 without FOpts, bytes."""
        m = self.max_mac_payload if repeater else self.max_mac_payload_no_repeater
        return m - _MAC_OVERHEAD


@dataclass(frozen=True)
class Region:
    """A LoRaWAN regional plan: its LoRa uplink data rates and access rules.

    Attributes
    ----------
    name
        Common name (``"EU868"``).
    data_rates
        LoRa uplink data rates, DR0 first.
    duty_cycle
        Fraction of time a device may transmit in a sub-band (None: no limit).
    preamble_symbols
        LoRa preamble length, symbols.
    source
        Documents the values come from.
    """

    name: str
    data_rates: tuple[DataRate, ...]
    duty_cycle: float | None
    preamble_symbols: int
    source: str


def _plan(entry: _Region) -> Region:
    """A regional plan of lorawan.toml; the dwell time holds on its 125 kHz channels."""
    rates = tuple(
        DataRate(i, sf, bw, m, m_nr, entry.dwell_time_s if bw == 125e3 else None)
        for i, (sf, bw, m, m_nr) in enumerate(entry.data_rates)
    )
    return Region(entry.name, rates, entry.duty_cycle, entry.preamble_symbols, entry.source)


REGIONS: dict[str, Region] = {entry.name: _plan(entry) for entry in DATA.region}


def region(name: str) -> Region:
    """The regional plan called ``name`` (case-insensitive: ``eu868`` works)."""
    key = str(name).strip().upper()
    if key not in REGIONS:
        raise UnknownNameError("region", str(name), REGIONS)
    return REGIONS[key]
