"""``sdt budget --sensor``: the whole node's charge per report and its battery life."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

from ..errors import SDTError
from .common import console, print_json, print_table

__all__ = ["NodeOptions", "print_node_budget", "refuse_without_sensor"]


@dataclass(frozen=True)
class NodeOptions:
    """The command-line settings of the node model (None: the sourced default)."""

    battery: str | None
    capacity_mah: float | None
    cell_voltage: float | None
    self_discharge_pct: float | None
    shelf_life_years: float | None
    window: str | None
    data_rate: str | None
    sensor_current_ua: float | None
    standby_ua: float | None
    turn_on_ms: float | None
    mcu_current_ma: float | None
    mcu_ms: float | None
    mcu_acquire_ma: float | None
    rx_current_ma: float | None
    sleep_ua: float | None
    regulator_ua: float | None
    rx2_sf: int | None


def _flag(name: str) -> str:
    return {"data_rate": "--dr", "mcu_ms": "--mcu-ms"}.get(name, "--" + name.replace("_", "-"))


def refuse_without_sensor(opts: NodeOptions) -> None:
    """A node option given without ``--sensor`` would be ignored: one line naming it."""
    given = [_flag(f.name) for f in fields(opts) if getattr(opts, f.name) is not None]
    if given:
        raise SDTError(
            f"{given[0]} needs --sensor: it sets the whole node's budget (battery life), and "
            f"without --sensor only the radio's table is printed; add --sensor NAME"
        )


def _non_negative(flag: str, value: float | None) -> None:
    if value is not None and not (math.isfinite(value) and value >= 0):
        raise SDTError(f"{flag} must be a number >= 0, got {value!r}")


def _positive(flag: str, value: float, unit: str) -> None:
    if not (math.isfinite(value) and value > 0):
        raise SDTError(f"{flag} must be > 0 {unit}, got {value!r}")


def _cell(opts: NodeOptions):
    from ..edge import Cell, cell

    own = {
        "--cell-voltage": opts.cell_voltage,
        "--self-discharge-pct": opts.self_discharge_pct,
        "--shelf-life-years": opts.shelf_life_years,
    }
    if opts.capacity_mah is None:
        given = [flag for flag, value in own.items() if value is not None]
        if given:
            raise SDTError(
                f"{given[0]} needs --capacity-mah (a cell of your own; the built-in cells "
                f"carry their own figures)"
            )
        return cell(opts.battery or "2xAA")
    if opts.battery is not None:
        raise SDTError("give --battery or --capacity-mah (a cell of your own), not both")
    missing = [flag for flag, value in own.items() if value is None]
    if missing:
        raise SDTError(
            f"--capacity-mah needs {', '.join(missing)} too: your cell's datasheet figures "
            f"(the life depends on each; none is guessed)"
        )
    _positive("--capacity-mah", opts.capacity_mah, "mAh")
    _positive("--cell-voltage", opts.cell_voltage, "V")  # type: ignore[arg-type]
    _positive("--shelf-life-years", opts.shelf_life_years, "years")  # type: ignore[arg-type]
    rate = opts.self_discharge_pct / 100  # type: ignore[operator]
    if not (math.isfinite(rate) and 0 <= rate < 1):
        raise SDTError(f"--self-discharge-pct must be 0 to < 100, got {opts.self_discharge_pct!r}")
    user = "user setting"
    return Cell(
        "own", opts.capacity_mah, opts.cell_voltage, rate, opts.shelf_life_years, user, user, user
    )  # type: ignore[arg-type]


def _sensor(spec, opts: NodeOptions):
    """The sensor with the user's own supply figures in place of (or beside) its sourced ones."""
    from ..specs import Supply, SupplyFigure

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


def _settings(opts: NodeOptions, *, axes, seconds, region, radio, repeater):
    from ..edge import NodeSettings, parse_interval

    window = 0.64 if opts.window is None else parse_interval(opts.window, "--window")
    settings = NodeSettings(
        interval_s=seconds,
        window_s=window,
        axes=axes,
        region=region,
        data_rate=opts.data_rate,
        radio=radio,
        mcu_time_s=None if opts.mcu_ms is None else opts.mcu_ms / 1e3,
        rx2_sf=opts.rx2_sf,
        repeater=repeater,
    )
    scaled = {
        "mcu_current_a": (opts.mcu_current_ma, 1e-3),
        "mcu_acquire_current_a": (opts.mcu_acquire_ma, 1e-3),
        "rx_current_a": (opts.rx_current_ma, 1e-3),
        "sleep_current_a": (opts.sleep_ua, 1e-6),
        "regulator_current_a": (opts.regulator_ua, 1e-6),
    }
    given = {k: v * scale for k, (v, scale) in scaled.items() if v is not None}
    return replace(settings, **given) if given else settings


def print_node_budget(reg, feature_set, sensor_name: str, *, axes, seconds, region, radio,
                      repeater, opts: NodeOptions, as_json: bool) -> None:  # fmt: skip
    """Resolve the sensor and cell, run the node model, print the table (or JSON)."""
    from ..edge import node_budget, node_rows, node_sources, node_summary

    for f in fields(opts):
        if f.name.endswith(("_ua", "_ma", "_ms")):
            _non_negative(_flag(f.name), getattr(opts, f.name))
    battery = _cell(opts)
    sensor = _sensor(reg.sensor(sensor_name), opts)
    settings = _settings(
        opts, axes=axes, seconds=seconds, region=region, radio=radio, repeater=repeater
    )
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
