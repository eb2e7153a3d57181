"""LoRa time on air: the Semtech SX127x formula.

Source: Semtech, *SX1276/77/78/79 datasheet*, Rev. 4 (March 2015), section
4.1.1.7 "Time on air" (page 31); the same formula is in Semtech AN1200.13
*LoRa Modem Designer's Guide*. With spreading factor SF, bandwidth BW (Hz),
coding rate 4/(4+CR), programmed preamble length n_preamble, payload length PL
(bytes, the whole PHY payload: for LoRaWAN the MAC header, frame header, port,
application payload and MIC), CRC = 1 when the payload CRC is on, IH = 1 for
implicit header mode and DE = 1 when low-data-rate optimisation is on:

    T_sym       = 2**SF / BW
    T_preamble  = (n_preamble + 4.25) * T_sym
    n_payload   = 8 + max(ceil((8 PL - 4 SF + 28 + 16 CRC - 20 IH) / (4 (SF - 2 DE))) * (CR + 4), 0)
    T_packet    = T_preamble + n_payload * T_sym

Low-data-rate optimisation "is mandated when the symbol duration exceeds
16 ms" (same datasheet, section 4.1.1.6): by default it is switched on exactly
then (SF11 and SF12 at 125 kHz).
"""

from __future__ import annotations

import math
from numbers import Integral

from ..errors import SDTError, shown

__all__ = [
    "LDRO_SYMBOL_S",
    "low_data_rate_optimize",
    "payload_symbols",
    "symbol_time_s",
    "time_on_air_s",
]

#: symbol duration above which the SX127x requires LowDataRateOptimize, s
LDRO_SYMBOL_S = 16e-3
#: largest payload the SX127x packet engine sends, bytes (8-bit length field)
MAX_PAYLOAD_BYTES = 255


def _check(sf: int, bandwidth_hz: float, coding_rate: int) -> None:
    if not (isinstance(sf, Integral) and 6 <= sf <= 12):
        raise SDTError(f"spreading factor must be an integer 6..12, got {shown(sf)}")
    if not (math.isfinite(bandwidth_hz) and bandwidth_hz > 0):
        raise SDTError(f"bandwidth must be a positive number of Hz, got {shown(bandwidth_hz)}")
    if coding_rate not in (1, 2, 3, 4):
        raise SDTError(f"coding rate CR must be 1..4 (4/5..4/8), got {shown(coding_rate)}")


def symbol_time_s(sf: int, bandwidth_hz: float) -> float:
    """Duration of one LoRa symbol, T_sym = 2**SF / BW, in seconds."""
    _check(sf, bandwidth_hz, 1)
    return 2.0**sf / float(bandwidth_hz)


def low_data_rate_optimize(sf: int, bandwidth_hz: float) -> bool:
    """Whether the SX127x requires LowDataRateOptimize: T_sym > 16 ms."""
    return symbol_time_s(sf, bandwidth_hz) > LDRO_SYMBOL_S


def payload_symbols(
    payload_bytes: int,
    sf: int,
    bandwidth_hz: float,
    *,
    coding_rate: int = 1,
    explicit_header: bool = True,
    crc: bool = True,
    low_data_rate: bool | None = None,
) -> int:
    """Number of symbols after the preamble, n_payload of the datasheet formula.

    Parameters
    ----------
    payload_bytes
        PHY payload length PL, bytes (0..255).
    sf, bandwidth_hz
        Spreading factor (6..12) and bandwidth, Hz.
    coding_rate
        CR in 4/(4+CR): 1 for 4/5 (LoRaWAN) to 4 for 4/8.
    explicit_header, crc
        Explicit header (LoRaWAN: yes) and payload CRC (LoRaWAN uplinks: on).
    low_data_rate
        LowDataRateOptimize; None switches it on when T_sym > 16 ms.
    """
    _check(sf, bandwidth_hz, coding_rate)
    if not (isinstance(payload_bytes, Integral) and 0 <= payload_bytes <= MAX_PAYLOAD_BYTES):
        raise SDTError(
            f"LoRa payload must be 0..{MAX_PAYLOAD_BYTES} bytes, got {shown(payload_bytes)}; "
            f"split the data over several messages"
        )
    if low_data_rate is None:
        low_data_rate = low_data_rate_optimize(sf, bandwidth_hz)
    numerator = 8 * payload_bytes - 4 * sf + 28 + 16 * int(crc) - 20 * int(not explicit_header)
    denominator = 4 * (sf - 2 * int(low_data_rate))
    return 8 + max(math.ceil(numerator / denominator) * (coding_rate + 4), 0)


def time_on_air_s(
    payload_bytes: int,
    sf: int,
    bandwidth_hz: float,
    *,
    coding_rate: int = 1,
    preamble_symbols: int = 8,
    explicit_header: bool = True,
    crc: bool = True,
    low_data_rate: bool | None = None,
) -> float:
    """Time on air of one LoRa packet, seconds (SX1276 datasheet 4.1.1.7).

    Parameters are those of :func:`payload_symbols`, plus ``preamble_symbols``,
    the programmed preamble length (LoRaWAN: 8, Regional Parameters 2.2.1).

    Examples
    --------
    A 10-byte application payload in a LoRaWAN frame (13 bytes of overhead,
    PL = 23) at SF7/125 kHz: 12.544 ms preamble + 48 symbols = 61.696 ms.

    >>> round(time_on_air_s(23, 7, 125e3) * 1e3, 3)
    61.696
    """
    if not (isinstance(preamble_symbols, Integral) and preamble_symbols >= 0):
        raise SDTError(
            f"preamble length must be a whole number >= 0, got {shown(preamble_symbols)}"
        )
    t_sym = symbol_time_s(sf, bandwidth_hz)
    n_payload = payload_symbols(
        payload_bytes,
        sf,
        bandwidth_hz,
        coding_rate=coding_rate,
        explicit_header=explicit_header,
        crc=crc,
        low_data_rate=low_data_rate,
    )
    return (preamble_symbols + 4.25) * t_sym + n_payload * t_sym
