"""Radio energy per message: transmit current x supply voltage x time on air; radio profiles.

E_msg = I_tx * V * T_packet (joules, with I in A, V in V, T in s). This is the
radio's transmit energy only: the two class A receive windows after each
uplink, waking up, the microcontroller, the accelerometer and sleep current
are not in it, so it is a lower bound on what a node spends per message (the
whole node: :mod:`.node`).

The built-in profiles and each figure's document, table and printed words are
in ``radios.toml`` beside this module: the bare SX1276 at four output powers
(Semtech datasheet Rev. 4, Table 6) and modules of the SX127x and SX126x
families (RAK4260, RAK3172), whose currents are what a node pays at the
module's supply pin, and which also give the receive current. The radio
table of ``sdt budget`` defaults to the bare SX1276 at +13 dBm
(``DEFAULT_RADIO``), the node model to the RAK4260 module at +14 dBm
(``NODE_RADIO``). Any other radio is a :class:`Radio` with the user's own
currents and voltage.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from pydantic import Field

from ..errors import SDTError, UnknownNameError, shown
from .sourced import DataModel, Figure, read_data

__all__ = ["DEFAULT_RADIO", "NODE_RADIO", "RADIOS", "Radio", "energy_per_message_j", "radio"]


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
    rx_current_a, rx_source
        Receive current, A, and its source (None: the node's default applies).
    kind, family
        "transceiver" (bare chip) or "module"; "SX127x" or "SX126x".
    """

    name: str
    tx_current_a: float
    supply_v: float
    tx_power_dbm: float | None = None
    source: str = ""
    rx_current_a: float | None = None
    rx_source: str = ""
    kind: str = ""
    family: str = ""

    def __post_init__(self) -> None:
        for field, value in (("tx_current_a", self.tx_current_a), ("supply_v", self.supply_v)):
            if not (math.isfinite(value) and value > 0):
                raise SDTError(f"radio {self.name!r}: {field} must be positive, got {shown(value)}")
        rx = self.rx_current_a
        if rx is not None and not (math.isfinite(rx) and rx >= 0):
            raise SDTError(f"radio {self.name!r}: rx_current_a must be >= 0, got {shown(rx)}")

    @property
    def tx_power_w(self) -> float:
        """Electrical power drawn while transmitting, W (I x V)."""
        return self.tx_current_a * self.supply_v


class RadioEntry(DataModel):
    """One ``[[radio]]`` of radios.toml."""

    name: str
    kind: str = Field(pattern="^(transceiver|module)$")
    family: str = Field(pattern="^SX12[67]x$")
    tx_power_dbm: float
    supply_v: float = Field(gt=0)
    tx: Figure
    rx: Figure | None = None


class _RadioFile(DataModel):
    radio: list[RadioEntry]


def _radio(entry: RadioEntry) -> Radio:
    rx = entry.rx
    return Radio(
        entry.name,
        entry.tx.value * 1e-3,
        entry.supply_v,
        entry.tx_power_dbm,
        entry.tx.cited(),
        None if rx is None else rx.value * 1e-3,
        "" if rx is None else rx.cited(),
        entry.kind,
        entry.family,
    )


#: the radios.toml entries (with every figure's source) by name
RADIO_ENTRIES: dict[str, RadioEntry] = {
    e.name: e for e in read_data("radios.toml", _RadioFile).radio
}
RADIOS: dict[str, Radio] = {name: _radio(entry) for name, entry in RADIO_ENTRIES.items()}
#: the radio of ``sdt budget``'s transmit-energy table: the bare transceiver
DEFAULT_RADIO = "sx1276-rfo-13dbm"
#: the radio of the node model: a module at EU868's +14 dBm
NODE_RADIO = "rak4260-14dbm"


def radio(name: str) -> Radio:
    """A built-in radio model by name (see ``RADIOS``)."""
    if name not in RADIOS:
        raise UnknownNameError("radio", name, RADIOS)
    return RADIOS[name]


def energy_per_message_j(time_on_air_s: float, model: Radio) -> float:
    """Transmit energy of one message, E = I x V x T_packet, joules."""
    if not (math.isfinite(time_on_air_s) and time_on_air_s >= 0):
        raise SDTError(f"time on air must be >= 0 s, got {shown(time_on_air_s)}")
    return model.tx_power_w * time_on_air_s
