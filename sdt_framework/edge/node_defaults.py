"""The node's own figures besides the accelerometer, each with where it comes from.

Every default below is a setting of :class:`~.node.NodeSettings`; a user with
measured figures for their own node passes them instead (``sdt budget --help``).

Radio receive current and node sleep current: Microchip online documentation,
section 7.4.1 "Current Consumption" of a LoRa module with an on-module
microcontroller (onlinedocs.microchip.com, GUID-BC5AB492-AA63-41E4-8A56-931408AA8F4F,
page GUID-798C30DB-83DA-4ED4-9D0A-5DF371351E60), typical, VDD = 3.3 V, 25 °C:
"RX; European band, fRF = 868 MHz, Bandwidth = 125 kHz | 12.68 | mA" and
"Low power modes | Standby | Sleep | 1.608 | µA" (microcontroller in standby,
transceiver asleep: the whole node apart from its accelerometer).

Receive windows (LoRaWAN class A): after each uplink the node opens RX1 and
RX2. With no downlink waiting (the usual case for a sensor that only
reports), each window stays open until the radio fails to find a preamble:
modelled as ``RX_SYMBOLS`` = 8 symbols, the LoRaWAN preamble length (the
regional plans of :mod:`.lorawan`), at the window's data rate. RX1 uses the
uplink's spreading factor (RX1 data-rate offset 0), at 125 kHz in EU868 and
500 kHz in US915 (Semtech LoRaMac-node ``RegionUS915.h``,
``DatarateOffsetsUS915``: uplink DR_0 answers on DR_10 = SF10/500 kHz; the same
spreading factor is assumed for the other rates). RX2 uses the region's fixed
rate, ``RX2_MODULATION``: LoRaMac-node ``RegionEU868.h`` ``EU868_RX_WND_2_DR
DR_0`` (SF12/125 kHz) and ``RegionUS915.h`` ``US915_RX_WND_2_DR DR_8``
(``DataratesUS915``/``BandwidthsUS915``: SF12, 500 kHz). A network that
configures another RX2 rate (The Things Network uses SF9 in EU868) passes
``--rx2-sf``. The time between the uplink and the windows (1 s and 2 s) is
spent asleep.

Feature computation on the microcontroller: an FFT of the window on a
Cortex-M4F class part. Time: measured by an NXP community expert
(community.nxp.com, thread "How to improve i.MX RT1024 RFFT execution time too
long?", accepted reply, table "FFT processing time on 120MHz K64 (m4) with HW
FPU operations (us)"): ``arm_cfft_f32`` of 2048 points in 2439 us, i.e.
2439 us x 120 MHz = 292 680 cycles; a window of N samples per axis is scaled
from it by N log2 N, and the cycles are run at ``MCU_CLOCK_HZ`` = 80 MHz (same
core, same cycles: an assumption). Current: STM32L496 (Cortex-M4F, 80 MHz)
feature list as quoted from ST's datasheet in the RT-Thread STM32L496-Nucleo
BSP README: "91 µA/MHz run mode (LDO Mode)", so 91 uA x 80 = 7.28 mA while
computing. The charge per cycle, 91 pC, does not depend on the clock chosen.
"""

from __future__ import annotations

__all__ = [
    "FFT_REFERENCE",
    "MCU_CLOCK_HZ",
    "MCU_CURRENT_A",
    "MCU_SOURCE",
    "RX2_MODULATION",
    "RX_CURRENT_A",
    "RX_SOURCE",
    "RX_SYMBOLS",
    "SLEEP_CURRENT_A",
    "SLEEP_SOURCE",
]

_MCHP = "Microchip online docs, 7.4.1 Current Consumption (LoRa module, VDD 3.3 V, 25 °C, typical)"
#: receive current, EU band 868 MHz, 125 kHz, A
RX_CURRENT_A = 12.68e-3
RX_SOURCE = f"{_MCHP}: RX, 868 MHz, BW 125 kHz, 12.68 mA"
#: node sleep current (microcontroller standby, transceiver sleep), A
SLEEP_CURRENT_A = 1.608e-6
SLEEP_SOURCE = f"{_MCHP}: Standby/Sleep, 1.608 uA"
#: symbols a receive window stays open without a downlink (LoRaWAN preamble length)
RX_SYMBOLS = 8
#: RX2 spreading factor and bandwidth per region
RX2_MODULATION = {"EU868": (12, 125e3), "US915": (12, 500e3)}
#: (FFT points, seconds, source) of the measured reference FFT
FFT_REFERENCE = (
    2048,
    2439e-6,
    "NXP community, i.MX RT1024 RFFT thread, accepted reply: arm_cfft_f32 2048 points "
    "on a 120 MHz K64 (Cortex-M4, HW FPU), 2439 us",
)
#: clock the feature computation runs at, Hz
MCU_CLOCK_HZ = 80e6
#: run current at that clock: 91 uA/MHz x 80 MHz, A
MCU_CURRENT_A = 91e-6 * 80
MCU_SOURCE = (
    "STM32L496 (Cortex-M4F) '91 µA/MHz run mode (LDO Mode)', as quoted in the RT-Thread "
    "STM32L496-Nucleo BSP README, at 80 MHz"
)
