"""The edge deployment budget: payload, LoRaWAN airtime, duty cycle, energy.

Pure functions with their formulas and sources in each module's docstring
(see also docs/edge.md). Rounding the features to their on-node dtype is
part of the benchmark's features: :func:`sdt_framework.features.quantise_features`.

Public API
----------
edge_budget, EdgeBudget, DataRateBudget, report_bytes
    One report per interval: per data rate, does it fit, time on air, duty
    cycle, messages, airtime and energy per day.
time_on_air_s, payload_symbols, symbol_time_s, low_data_rate_optimize
    The Semtech SX127x time-on-air formula.
region, REGIONS, Region, DataRate, phy_payload_bytes, OVERHEAD_BYTES
    LoRaWAN framing (13 bytes) and the EU868 / US915 data-rate plans.
radio, RADIOS, Radio, energy_per_message_j, DEFAULT_RADIO, NODE_RADIO
    Radio profiles (radios.toml: the bare SX1276 and SX127x/SX126x modules, each
    current with its datasheet) and transmit energy from them.
node_budget(...) -> NodeBudget, NodeSettings ; cell(name) -> Cell
    The whole node's charge per report and its battery life, capped at the
    cell's shelf life (node.toml, cells.toml hold every figure's source).
budget_rows, budget_summary ; node_rows, node_summary, node_sources
    Both budgets as the table and lines ``sdt budget`` and the report print.
parse_interval, format_interval
    ``"10min"`` <-> 600 s.
"""

from __future__ import annotations

from .budget import SECONDS_PER_DAY, DataRateBudget, EdgeBudget, edge_budget, report_bytes
from .cells import Cell, cell
from .energy import DEFAULT_RADIO, NODE_RADIO, RADIOS, Radio, energy_per_message_j, radio
from .interval import format_interval, parse_interval
from .lora import low_data_rate_optimize, payload_symbols, symbol_time_s, time_on_air_s
from .lorawan import OVERHEAD_BYTES, REGIONS, DataRate, Region, phy_payload_bytes, region
from .node import NodeBudget, NodeSettings, node_budget
from .node_table import node_rows, node_sources, node_summary
from .table import budget_rows, budget_summary

__all__ = [
    "DEFAULT_RADIO",
    "NODE_RADIO",
    "OVERHEAD_BYTES",
    "RADIOS",
    "REGIONS",
    "SECONDS_PER_DAY",
    "Cell",
    "DataRate",
    "DataRateBudget",
    "EdgeBudget",
    "NodeBudget",
    "NodeSettings",
    "Radio",
    "Region",
    "budget_rows",
    "budget_summary",
    "cell",
    "edge_budget",
    "energy_per_message_j",
    "format_interval",
    "low_data_rate_optimize",
    "node_budget",
    "node_rows",
    "node_sources",
    "node_summary",
    "parse_interval",
    "payload_symbols",
    "phy_payload_bytes",
    "radio",
    "region",
    "report_bytes",
    "symbol_time_s",
    "time_on_air_s",
]
