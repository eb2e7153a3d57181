"""The node's own figures besides the accelerometer, each with where it comes from.

The currents, the clock and the reference FFT are read from ``node.toml``
beside this module (every figure with its document, table and printed words);
the LoRaWAN receive-window figures below from ``lorawan.toml`` (protocol facts,
each with its source). Every default is a setting of :class:`~.node.NodeSettings`; a
user with measured figures for their own node passes them instead
(``sdt budget --help``).

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
spent asleep. A report split over several uplinks opens a pair of windows
after each of them.
"""

from __future__ import annotations

from .lorawan import DATA as LORAWAN
from .sourced import DataModel, Figure, read_data

__all__ = [
    "FFT_REFERENCE",
    "FIGURES",
    "MCU_CLOCK_HZ",
    "MCU_CURRENT_A",
    "MCU_SOURCE",
    "MCU_STOP2_A",
    "NOT_COUNTED",
    "REGULATOR_A",
    "REGULATOR_SOURCE",
    "RX2_MODULATION",
    "RX_CURRENT_A",
    "RX_SOURCE",
    "RX_SYMBOLS",
    "SLEEP_CURRENT_A",
    "SLEEP_SOURCE",
]


class NodeFigures(DataModel):
    """node.toml: one :class:`~.sourced.Figure` per default."""

    rx: Figure
    sleep: Figure
    mcu_run: Figure
    mcu_clock: Figure
    mcu_stop2: Figure
    fft_points: Figure
    fft_time: Figure
    fft_clock: Figure
    regulator: Figure


#: node.toml, every figure with its source
FIGURES = read_data("node.toml", NodeFigures)

#: receive current of a radio profile without its own, A
RX_CURRENT_A = FIGURES.rx.value * 1e-3
RX_SOURCE = f"{FIGURES.rx.cited()}: {FIGURES.rx.value:g} mA"
#: node sleep current (microcontroller standby, transceiver sleep), A
SLEEP_CURRENT_A = FIGURES.sleep.value * 1e-6
SLEEP_SOURCE = f"{FIGURES.sleep.cited()}: {FIGURES.sleep.value:g} uA"
#: clock the microcontroller runs at, Hz, and its run current there, A
MCU_CLOCK_HZ = FIGURES.mcu_clock.value * 1e6
MCU_CURRENT_A = FIGURES.mcu_run.value * 1e-6 * FIGURES.mcu_clock.value
MCU_SOURCE = (
    f"{FIGURES.mcu_run.doc}: '{FIGURES.mcu_run.printed}', at {FIGURES.mcu_clock.value:g} MHz"
)
#: Stop 2 current, A: the floor of the acquiring stage (not the default)
MCU_STOP2_A = FIGURES.mcu_stop2.value * 1e-6
#: quiescent current of the regulator, A
REGULATOR_A = FIGURES.regulator.value * 1e-6
REGULATOR_SOURCE = f"{FIGURES.regulator.cited()}: {FIGURES.regulator.value:g} uA typical"
#: (FFT points, seconds, source, clock Hz) of the measured reference FFT
FFT_REFERENCE = (
    int(FIGURES.fft_points.value),
    FIGURES.fft_time.value * 1e-6,
    f"{FIGURES.fft_time.doc}: arm_cfft_f32 {FIGURES.fft_points.value:g} points on a "
    f"{FIGURES.fft_clock.value:g} MHz K64 (Cortex-M4, HW FPU), {FIGURES.fft_time.value:g} us",
    FIGURES.fft_clock.value * 1e6,
)
#: symbols a receive window stays open without a downlink (LoRaWAN preamble length)
RX_SYMBOLS = LORAWAN.receive_window.symbols
#: RX2 spreading factor and bandwidth per region (lorawan.toml, with their sources)
RX2_MODULATION = {r.name: (r.rx2_sf, r.rx2_bandwidth_hz) for r in LORAWAN.region}
#: what the node model leaves out, said with every life it gives
NOT_COUNTED = (
    "the life is an estimate from typical datasheet figures at room temperature; not counted: "
    "cold or heat, the cell's voltage drop under the radio's current pulses (Li-SOCl2 "
    "passivation), part-to-part spread (maximum rather than typical currents), confirmed "
    "uplinks, retransmissions, downlinks and MAC commands, the join, and board leakage"
)
