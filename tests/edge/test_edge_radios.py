"""Radio profiles and the node's own figures (issue 40, item 7): data files with their sources."""

from __future__ import annotations

import math
import re

import pytest

from sdt_framework.edge import node_defaults as nd
from sdt_framework.edge.energy import DEFAULT_RADIO, NODE_RADIO, RADIO_ENTRIES, RADIOS
from sdt_framework.specs.supply import printed_numbers

#: the printed unit -> the field's unit, for finding the value in the quote
TO_FIELD = {"": 1.0, "mA": 1.0, "Ah": 1e3, "µA/MHz": 1.0, "MHz": 1.0, "points": 1.0, "us": 1.0}


def _numbers(text: str) -> list[float]:
    return printed_numbers(re.sub(r"(\d)([^\d\s.,;|)])", r"\1 \2", text))


def _in_printed(figure) -> bool:
    scale = TO_FIELD[figure.printed_unit]
    numbers = _numbers(figure.printed)
    return any(math.isclose(n * scale, figure.value, rel_tol=1e-12) for n in numbers)


def test_every_radio_figure_is_in_its_printed_words():
    for entry in RADIO_ENTRIES.values():
        assert _in_printed(entry.tx), entry.name
        assert entry.rx is None or _in_printed(entry.rx), entry.name
        assert math.isclose(entry.tx_power_dbm, float(re.search(r"(\d+)dbm", entry.name)[1]))


def test_module_profiles_of_both_families_beside_the_bare_transceiver():
    kinds = {(r.kind, r.family) for r in RADIOS.values()}
    assert {("transceiver", "SX127x"), ("module", "SX127x"), ("module", "SX126x")} <= kinds
    # the figures the module datasheets print (RAK4260: 33.1 mA at 14 dBm, 13.6 mA RX;
    # RAK3172LP-SiP: 39.1 mA at 14 dBm, 9.69 mA RX) against the bare SX1276's 29 mA at 13 dBm
    assert RADIOS["rak4260-14dbm"].tx_current_a == pytest.approx(33.1e-3)
    assert RADIOS["rak4260-14dbm"].rx_current_a == pytest.approx(13.6e-3)
    assert RADIOS["rak3172lp-14dbm"].tx_current_a == pytest.approx(39.1e-3)
    assert RADIOS["rak3172lp-14dbm"].rx_current_a == pytest.approx(9.69e-3)
    assert RADIOS["sx1276-rfo-13dbm"].rx_current_a is None  # Table 6's RX rows not read
    assert RADIOS[NODE_RADIO].kind == "module" and RADIOS[DEFAULT_RADIO].kind == "transceiver"


def test_every_node_figure_is_in_its_printed_words():
    for name in type(nd.FIGURES).model_fields:
        figure = getattr(nd.FIGURES, name)
        assert figure.doc and figure.where
        assert _in_printed(figure), name
    assert pytest.approx(1.6e-6) == nd.REGULATOR_A  # MCP1700: "Iq — 1.6 4 µA"
    assert pytest.approx(91e-6 * 80) == nd.MCU_CURRENT_A
    assert nd.FFT_REFERENCE[:2] == (2048, pytest.approx(2439e-6))
