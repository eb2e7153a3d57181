"""``sdt budget --sensor``: the whole node's charge per report and its battery life."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from ..errors import SDTError
from .common import console, print_json, print_table

__all__ = ["NodeOptions", "print_node_budget"]


@dataclass(frozen=True)
class NodeOptions:
    """The command-line settings of the node model (None: the sourced default)."""

    battery: str
    capacity_mah: float | None
    cell_voltage: float
    self_discharge_pct: float | None
    window: str
    data_rate: str | None
    sensor_current_ua: float | None
    standby_ua: float | None
    turn_on_ms: float | None
    mcu_current_ma: float | None
    mcu_ms: float | None
    rx_current_ma: float | None
    sleep_ua: float | None
    rx2_sf: int | None


def _non_negative(flag: str, value: float | None) -> None:
    if value is not None and not (math.isfinite(value) and value >= 0):
        raise SDTError(f"{flag} must be a number >= 0, got {value!r}")


def _cell(opts: NodeOptions):
    from ..edge.cells import Cell, cell

    if opts.capacity_mah is None:
        if opts.self_discharge_pct is not None:
            raise SDTError("--self-discharge-pct needs --capacity-mah (a cell of your own)")
        return cell(opts.battery)
    if not (math.isfinite(opts.capacity_mah) and opts.capacity_mah > 0):
        raise SDTError(f"--capacity-mah must be > 0, got {opts.capacity_mah!r}")
    rate = None if opts.self_discharge_pct is None else opts.self_discharge_pct / 100
    if rate is not None and not (0 <= rate < 1):
        raise SDTError(f"--self-discharge-pct must be 0 to < 100, got {opts.self_discharge_pct!r}")
    return Cell("own", opts.capacity_mah, opts.cell_voltage, rate, "user setting", "user setting")


def _sensor(spec, opts: NodeOptions):
    """The sensor with the user's own supply figures in place of (or beside) its sourced ones."""
    from ..specs.supply import Supply, SupplyFigure

    given = {
        "measure_ua": opts.sensor_current_ua,
        "standby_ua": opts.standby_ua,
        "turn_on_ms": opts.turn_on_ms,
    }
    if all(v is None for v in given.values()):
        return spec
    user = {"doc": "user setting", "where": "command line", "printed": "given"}
    missing = SupplyFigure(absent="not on record for this sensor")
    current = spec.supply.figures() if spec.supply is not None else {k: missing for k in given}
    figures = {
        key: current[key] if value is None else SupplyFigure(value=value, **user)
        for key, value in given.items()
    }
    mode = spec.supply.mode if spec.supply is not None else ""
    return spec.model_copy(update={"supply": Supply(**figures, mode=mode)})


def print_node_budget(reg, feature_set, sensor_name: str, *, axes, seconds, region, radio,
                      opts: NodeOptions, as_json: bool) -> None:  # fmt: skip
    """Resolve the sensor and cell, run the node model, print the table (or JSON)."""
    from ..edge import parse_interval
    from ..edge.node import NodeSettings, node_budget
    from ..edge.node_table import node_rows, node_sources, node_summary

    for flag, value in (
        ("--sensor-current-ua", opts.sensor_current_ua),
        ("--standby-ua", opts.standby_ua),
        ("--turn-on-ms", opts.turn_on_ms),
        ("--mcu-current-ma", opts.mcu_current_ma),
        ("--mcu-ms", opts.mcu_ms),
        ("--rx-current-ma", opts.rx_current_ma),
        ("--sleep-ua", opts.sleep_ua),
    ):
        _non_negative(flag, value)
    battery = _cell(opts)
    sensor = _sensor(reg.sensor(sensor_name), opts)
    settings = NodeSettings(
        interval_s=seconds,
        window_s=parse_interval(opts.window),
        axes=axes,
        region=region,
        data_rate=opts.data_rate,
        radio=radio,
        mcu_time_s=None if opts.mcu_ms is None else opts.mcu_ms / 1e3,
        rx2_sf=opts.rx2_sf,
    )
    if opts.mcu_current_ma is not None:
        settings = replace(settings, mcu_current_a=opts.mcu_current_ma / 1e3)
    if opts.rx_current_ma is not None:
        settings = replace(settings, rx_current_a=opts.rx_current_ma / 1e3)
    if opts.sleep_ua is not None:
        settings = replace(settings, sleep_current_a=opts.sleep_ua / 1e6)
    result = node_budget(sensor, feature_set, battery, settings)
    if as_json:
        print_json(result.to_dict())
        return
    from rich import box
    from rich.table import Table

    console.print(node_summary(result), highlight=False, soft_wrap=True, markup=False)
    columns, rows = node_rows(result)
    out = Table(box=box.SIMPLE_HEAD, padding=0, pad_edge=False, show_edge=False)
    for i, column in enumerate(columns):
        widest = max(len(row[i]) for row in rows)
        out.add_column(column, justify="left" if i == 0 else "right", min_width=widest)
    for row in rows:
        out.add_row(*row)
    print_table(out)
    for line in node_sources(result):
        console.print(line, highlight=False, soft_wrap=True, markup=False)
