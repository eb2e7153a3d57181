"""Radio energy per message: transmit current x supply voltage x time on air.

E_msg = I_tx * V * T_packet (joules, with I in A, V in V, T in s). This is the
radio's transmit energy only: the two class A receive windows after each
uplink, waking up, the microcontroller, the accelerometer and sleep current
are not in it, so it is a lower bound on what a node spends per message.

Default currents: Semtech, *SX1276/77/78/79 datasheet*, Rev. 4 (March 2015),
section 2.5.1, Table 6 "Power Consumption Specification", IDDT "supply current
in transmit mode with impedance matching" (typical): 20 mA at +7 dBm and 29 mA
at +13 dBm on the RFO_LF/HF pin, 87 mA at +17 dBm and 120 mA at +20 dBm on
PA_BOOST. The default radio is the +13 dBm point, the tabulated output closest
below EU868's +14 dBm ERP limit. Supply 3.3 V: the voltage at which Semtech
states its SX127x electrical tables (e.g. SX1272/73 datasheet Rev. 2, section
2.5.5, "Supply voltage = 3.3 V"). Any other radio is a :class:`Radio` with the
user's own current and voltage.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import SDTError, UnknownNameError

__all__ = ["DEFAULT_RADIO", "RADIOS", "Radio", "energy_per_message_j", "radio"]

_SX1276 = "Semtech SX1276/77/78/79 datasheet Rev. 4 (2015), Table 6, IDDT typical"


@dataclass(frozen=True)
class Radio:
    """A transmit current/voltage model of a radio.

    Attributes
    ----------
    name
        Short name (``"sx1276-rfo-13dbm"``).
    tx_current_a
        Supply current while transmitting, A.
    supply_v
        Supply voltage, V.
    tx_power_dbm
        Output power the current belongs to, dBm (documentation only).
    source
        Where the current comes from.
    """

    name: str
    tx_current_a: float
    supply_v: float
    tx_power_dbm: float | None = None
    source: str = ""

    def __post_init__(self) -> None:
        for field, value in (("tx_current_a", self.tx_current_a), ("supply_v", self.supply_v)):
            if not (math.isfinite(value) and value > 0):
                raise SDTError(f"radio {self.name!r}: {field} must be positive, got {value!r}")

    @property
    def tx_power_w(self) -> float:
        """Electrical power drawn while transmitting, W (I x V)."""
        return self.tx_current_a * self.supply_v


RADIOS: dict[str, Radio] = {
    r.name: r
    for r in (
        Radio("sx1276-rfo-7dbm", 20e-3, 3.3, 7, f"{_SX1276}, +7 dBm on RFO_LF/HF"),
        Radio("sx1276-rfo-13dbm", 29e-3, 3.3, 13, f"{_SX1276}, +13 dBm on RFO_LF/HF"),
        Radio("sx1276-boost-17dbm", 87e-3, 3.3, 17, f"{_SX1276}, +17 dBm on PA_BOOST"),
        Radio("sx1276-boost-20dbm", 120e-3, 3.3, 20, f"{_SX1276}, +20 dBm on PA_BOOST"),
    )
}
DEFAULT_RADIO = "sx1276-rfo-13dbm"


def radio(name: str) -> Radio:
    """A built-in radio model by name (see ``RADIOS``)."""
    if name not in RADIOS:
        raise UnknownNameError("radio", name, RADIOS)
    return RADIOS[name]


def energy_per_message_j(time_on_air_s: float, model: Radio) -> float:
    """Transmit energy of one message, E = I x V x T_packet, joules."""
    if not (math.isfinite(time_on_air_s) and time_on_air_s >= 0):
        raise SDTError(f"time on air must be >= 0 s, got {time_on_air_s!r}")
    return model.tx_power_w * time_on_air_s
