"""``sdt budget``: what sending a feature set over LoRaWAN costs a node per day."""

from __future__ import annotations

from dataclasses import replace

import typer

from ..errors import SDTError
from .common import console, print_json, print_table, registry

__all__ = ["budget"]


def budget(
    ctx: typer.Context,
    features: str = typer.Option(
        "paper8",
        "--features",
        help="Feature set (paper8), or registered sets joined by '+' (sdt features list).",
    ),
    axes: int = typer.Option(3, "--axes", help="Axes per report (3: triaxial)."),
    interval: str = typer.Option(
        "10min", "--interval", help="Time between reports, with its unit: 30s, 10min, 1h, 1d."
    ),
    region: str = typer.Option("EU868", "--region", help="LoRaWAN regional plan: EU868, US915."),
    dtype: str | None = typer.Option(
        None, "--dtype", help="Send values as float16 or float32 (default: the set's dtype)."
    ),
    radio: str | None = typer.Option(
        None,
        "--radio",
        help="Radio profile: sx1276-rfo-7dbm, sx1276-rfo-13dbm (the table's default), "
        "sx1276-boost-17dbm, sx1276-boost-20dbm (bare SX1276); modules rak4260-14dbm (the "
        "node's default with --sensor), rak4260-17dbm, rak3172lp-14dbm, rak3172-20dbm.",
    ),
    tx_current_ma: float | None = typer.Option(
        None, "--tx-current-ma", help="Override the radio's transmit current, mA."
    ),
    voltage: float | None = typer.Option(
        None, "--voltage", help="Override the radio table's supply, V (not with --sensor)."
    ),
    repeater: bool = typer.Option(
        True,
        "--repeater/--no-repeater",
        help="Payload limits of the repeater-compatible table (default) or the larger one.",
    ),
    sensor: str | None = typer.Option(
        None,
        "--sensor",
        help="Budget the whole node with this sensor (a part's mode in brackets: "
        "'adxl345-ds\\[odr=1600]'): charge per report by consumer, average current, battery life. "
        "Every option below needs it.",
    ),
    battery: str | None = typer.Option(
        None, "--battery", help="Cell with --sensor: 2xAA (default), C, D."
    ),
    capacity_mah: float | None = typer.Option(
        None, "--capacity-mah", help="Your own cell's capacity, mAh (replaces --battery)."
    ),
    cell_voltage: float | None = typer.Option(
        None, "--cell-voltage", help="Your own cell's voltage, V (with --capacity-mah)."
    ),
    self_discharge_pct: float | None = typer.Option(
        None, "--self-discharge-pct", help="Your own cell's self-discharge, % per year."
    ),
    shelf_life_years: float | None = typer.Option(
        None, "--shelf-life-years", help="Your own cell's rated shelf life, years (the cap)."
    ),
    window: str | None = typer.Option(
        None, "--window", help="Acquisition per report (default 0.64s)."
    ),
    data_rate: str | None = typer.Option(
        None, "--dr", help="Data rate (default: the slowest that fits one uplink legally)."
    ),
    sensor_current_ua: float | None = typer.Option(
        None, "--sensor-current-ua", help="Sensor supply current measuring, uA (your own)."
    ),
    standby_ua: float | None = typer.Option(
        None, "--standby-ua", help="Sensor standby current, uA (your own)."
    ),
    turn_on_ms: float | None = typer.Option(
        None, "--turn-on-ms", help="Sensor turn-on time, ms (your own)."
    ),
    mcu_current_ma: float | None = typer.Option(
        None, "--mcu-current-ma", help="Microcontroller run current, mA (default 7.28)."
    ),
    mcu_ms: float | None = typer.Option(
        None, "--mcu-ms", help="Feature computation per report, ms (default: FFT scaled)."
    ),
    mcu_acquire_ma: float | None = typer.Option(
        None,
        "--mcu-acquire-ma",
        help="Microcontroller current while the window is acquired, mA (default: its run "
        "current, awake throughout; 0.00257 is Stop 2 between FIFO reads).",
    ),
    rx_current_ma: float | None = typer.Option(
        None, "--rx-current-ma", help="Radio receive current, mA (default: the radio's)."
    ),
    sleep_ua: float | None = typer.Option(
        None, "--sleep-ua", help="Node sleep current, uA (default 1.608)."
    ),
    regulator_ua: float | None = typer.Option(
        None, "--regulator-ua", help="Regulator quiescent current, uA (default 1.6)."
    ),
    rx2_sf: int | None = typer.Option(
        None, "--rx2-sf", help="RX2 spreading factor your network uses (default: the region's)."
    ),
    as_json: bool = typer.Option(False, "--json", help="Print JSON for scripts."),
) -> None:
    """Payload, LoRaWAN airtime, duty cycle and radio energy of one report per interval.

    With --sensor: the whole node, one stage per consumer (accelerometer
    measuring and in standby, microcontroller acquiring and computing, radio
    transmit, RX1 and RX2 after each uplink, regulator, sleep), each with its
    source; average current and battery life in years, an estimate under
    typical figures, capped at the cell's rated shelf life.

    One report is one window's feature vector on every axis; with --sensor, the
    microcontroller's time is the feature set's FFTs per axis (paper8: one;
    orders: three, plus one zero-padded FFT for the tachless speed estimate). For each data rate
    of the region: whether it fits one uplink (else how many), time on air
    (Semtech SX127x formula), the shortest interval the duty cycle allows,
    airtime and transmit energy per day. Formulas and sources: docs/edge.md.

    Example:

      sdt budget --features paper8 --axes 3 --interval 10min --region EU868

      sdt budget --dtype float16 --region US915 --json

      sdt budget --sensor adxl345 --battery 2xAA --interval 10min

      sdt budget --sensor adxl345 --battery 2xAA --features orders   # order features' FFTs
    """
    from ..edge import (
        DEFAULT_RADIO,
        NODE_RADIO,
        budget_rows,
        budget_summary,
        edge_budget,
        parse_interval,
    )
    from ..edge import radio as radio_named
    from ..features import resolve_feature_set
    from .budget_node import NodeOptions, print_node_budget, refuse_without_sensor

    opts = NodeOptions(
        battery, capacity_mah, cell_voltage, self_discharge_pct, shelf_life_years, window,
        data_rate, sensor_current_ua, standby_ua, turn_on_ms, mcu_current_ma, mcu_ms,
        mcu_acquire_ma, rx_current_ma, sleep_ua, regulator_ua, rx2_sf,
    )  # fmt: skip
    if sensor is None:
        refuse_without_sensor(opts)
    elif voltage is not None:
        raise SDTError(
            "--voltage sets the radio table's supply; with --sensor the energy is the charge x "
            "the cell's voltage (--cell-voltage with --capacity-mah for a cell of your own)"
        )
    if axes < 1:
        raise SDTError(f"--axes must be 1 or more, got {axes}")
    if dtype is not None and dtype not in ("float16", "float32"):
        raise SDTError(f"--dtype must be float16 or float32, got {dtype!r}")
    seconds = parse_interval(interval, "--interval")
    model = radio_named(radio or (NODE_RADIO if sensor is not None else DEFAULT_RADIO))
    if tx_current_ma is not None or voltage is not None:
        model = replace(
            model,
            name=f"{model.name} (custom)",
            tx_current_a=model.tx_current_a if tx_current_ma is None else tx_current_ma / 1e3,
            supply_v=model.supply_v if voltage is None else voltage,
            source="user override",
        )
    spec = resolve_feature_set(registry(ctx), features)
    if sensor is not None:
        print_node_budget(
            registry(ctx), spec if dtype is None else spec.with_dtype(dtype), sensor,
            axes=axes, seconds=seconds, region=region, radio=model, repeater=repeater,
            opts=opts, as_json=as_json,
        )  # fmt: skip
        return
    result = edge_budget(
        spec,
        axes=axes,
        interval_s=seconds,
        region=region,
        radio=model,
        dtype=dtype,
        repeater=repeater,
    )
    if as_json:
        print_json(result.to_dict())
        return
    from rich import box
    from rich.table import Table

    columns, rows = budget_rows(result)
    console.print(budget_summary(result), highlight=False, soft_wrap=True, markup=False)
    out = Table(box=box.SIMPLE_HEAD, padding=0, pad_edge=False, show_edge=False)
    for i, column in enumerate(columns):
        widest = max(len(row[i]) for row in rows)  # data never wraps; headers may
        out.add_column(column, justify="left" if i < 2 else "right", min_width=widest)
    for row in rows:
        out.add_row(*row)
    print_table(out)
