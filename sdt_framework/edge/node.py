"""The whole node's charge per report, one stage per consumer, and the battery's life.

Every reporting interval T the node wakes its accelerometer, records one
window of W seconds on every axis, computes the features, sends one LoRaWAN
class A uplink and listens in RX1 and RX2, and sleeps the rest of the time.
Per report, with I the supply current of each consumer (A) and t its time (s):

    accelerometer measuring   Q_acq   = I_meas (t_on + W)
    accelerometer asleep      Q_stby  = I_stby (T - t_on - W)
    microcontroller features  Q_mcu   = I_mcu t_mcu,  t_mcu = axes t_FFT(N)
    radio transmit            Q_tx    = I_tx ToA       (airtime model, :mod:`.lora`)
    radio RX1, RX2            Q_rx    = I_rx n_sym T_sym(window's data rate)
    node sleep                Q_sleep = I_sleep (T - t_mcu - ToA - t_rx1 - t_rx2)

The charge per report is the sum; the average current is that over T; the
battery's life follows from :func:`.cells.life_years`. Every current is drawn
from the battery through a linear regulator, so the battery delivers the
same current; energy per report is charge x the cell's voltage. Each stage
carries its source (:mod:`.node_defaults`, the sensor's supply figures,
:mod:`.energy`); a stage whose current is not known is listed as not counted,
never filled in.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

from ..errors import SDTError
from ..specs import FeatureSetSpec, SensorSpec
from . import node_defaults as nd
from .budget import DataRateBudget, edge_budget
from .cells import Cell, life_years
from .energy import DEFAULT_RADIO, Radio
from .lora import symbol_time_s
from .lorawan import region as region_named

__all__ = ["NodeBudget", "NodeSettings", "Stage", "battery_life_years", "node_budget"]


@dataclass(frozen=True)
class NodeSettings:
    """What the node does besides its accelerometer; every default is sourced (node_defaults)."""

    interval_s: float = 600.0
    window_s: float = 0.64
    axes: int = 3
    region: str = "EU868"
    data_rate: str | None = None
    radio: Radio | str = DEFAULT_RADIO
    rx_current_a: float = nd.RX_CURRENT_A
    rx_symbols: int = nd.RX_SYMBOLS
    rx2_sf: int | None = None
    sleep_current_a: float = nd.SLEEP_CURRENT_A
    mcu_current_a: float | None = nd.MCU_CURRENT_A
    mcu_time_s: float | None = None

    def __post_init__(self) -> None:
        for name in ("interval_s", "window_s"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise SDTError(f"{name.removesuffix('_s')} must be > 0 s, got {value!r}")
        for name in ("rx_current_a", "sleep_current_a", "mcu_current_a", "mcu_time_s"):
            value = getattr(self, name)
            if value is not None and not (math.isfinite(value) and value >= 0):
                unit = "s" if name.endswith("_s") else "A"
                raise SDTError(f"{name} must be >= 0 {unit}, got {value!r}")
        if not (isinstance(self.rx_symbols, int) and self.rx_symbols >= 0):
            raise SDTError(
                f"receive window must be a whole number of symbols, got {self.rx_symbols!r}"
            )


@dataclass(frozen=True)
class Stage:
    """One consumer's share of a report: current, time, charge (None: not counted), source."""

    consumer: str
    current_a: float | None
    time_s: float
    charge_c: float | None
    source: str
    note: str = ""


@dataclass(frozen=True)
class NodeBudget:
    """A node's charge per report by consumer, average current and battery life."""

    sensor: str
    sensor_mode: str
    battery: Cell
    region: str
    data_rate: str
    interval_s: float
    stages: tuple[Stage, ...]
    charge_per_report_c: float
    energy_per_report_j: float
    average_current_a: float
    life_years: float
    notes: tuple[str, ...] = field(default=())

    def to_dict(self) -> dict:
        """JSON-ready form."""
        data = asdict(self)
        data["life_years"] = None if math.isinf(self.life_years) else self.life_years
        return data


def _fft_time_s(samples: int) -> float:
    """The reference FFT's cycles (at 120 MHz) scaled by N log2 N, run at the node's clock."""
    points, seconds, _ = nd.FFT_REFERENCE
    cycles = seconds * 120e6 * samples * math.log2(max(samples, 2)) / (points * math.log2(points))
    return cycles / nd.MCU_CLOCK_HZ


def _pick_rate(rows: tuple[DataRateBudget, ...], wanted: str | None) -> DataRateBudget:
    """The data rate asked for, else the longest-range one that carries the report legally.

    When no rate carrying the report in one uplink keeps the duty cycle or dwell
    time, the fastest such rate is returned and the caller's checks name the problem.
    """
    if wanted is not None:
        for row in rows:
            if row.data_rate.lower() == wanted.strip().lower():
                return row
        names = ", ".join(r.data_rate for r in rows)
        raise SDTError(f"data rate {wanted!r} is not in this region's plan; use one of {names}")
    fitting = [r for r in rows if r.fits]
    if not fitting:
        raise SDTError("the report fits no single uplink of this region; pass --dr to split it")
    legal = [r for r in fitting if r.duty_cycle_ok is not False and r.dwell_ok is not False]
    if not legal:
        return min(fitting, key=lambda r: r.time_on_air_s)
    return max(legal, key=lambda r: r.time_on_air_s)


def _figure(sensor: SensorSpec, name: str) -> tuple[float | None, str]:
    supply = sensor.supply
    if supply is None:
        return None, f"{sensor.name} has no supply figures on record"
    figure = supply.figures()[name]
    return figure.value, figure.cited()


def node_budget(
    sensor: SensorSpec,
    feature_set: FeatureSetSpec,
    battery: Cell,
    settings: NodeSettings | None = None,
) -> NodeBudget:
    """Charge per report by consumer, average current and life of ``battery`` (module notes)."""
    s = settings or NodeSettings()
    budget = edge_budget(
        feature_set, axes=s.axes, interval_s=s.interval_s, region=s.region, radio=s.radio
    )
    row = _pick_rate(budget.rows, s.data_rate)
    rate = next(r for r in region_named(s.region).data_rates if r.name == row.data_rate)
    notes: list[str] = []
    i_meas, meas_src = _figure(sensor, "measure_ua")
    i_stby, stby_src = _figure(sensor, "standby_ua")
    t_on_ms, on_src = _figure(sensor, "turn_on_ms")
    if i_meas is None:
        raise SDTError(
            f"sensor {sensor.name!r}: no measuring supply current ({meas_src}); "
            f"give it with --sensor-current-ua"
        )
    t_on = (t_on_ms or 0.0) / 1e3
    if t_on_ms is None:
        notes.append(f"turn-on time not counted ({on_src})")
    if sensor.sampling_rate_hz == "native":
        raise SDTError(f"sensor {sensor.name!r} samples at the recording's rate: no node to budget")
    samples = max(1, round(s.window_s * float(sensor.sampling_rate_hz)))
    t_mcu = s.mcu_time_s if s.mcu_time_s is not None else s.axes * _fft_time_s(samples)
    mcu_src = (
        "user setting"
        if s.mcu_time_s is not None
        else f"{nd.FFT_REFERENCE[2]}, scaled to {samples} points x {s.axes} axes at 80 MHz"
    )
    if s.mcu_current_a == nd.MCU_CURRENT_A:
        mcu_src += f"; current: {nd.MCU_SOURCE}"
    t_acq = t_on + s.window_s
    t_rx1 = s.rx_symbols * symbol_time_s(rate.sf, 500e3 if s.region.upper() == "US915" else 125e3)
    rx2_sf, rx2_bw = nd.RX2_MODULATION[s.region.upper()]
    rx2_sf = s.rx2_sf or rx2_sf
    t_rx2 = s.rx_symbols * symbol_time_s(rx2_sf, rx2_bw)
    busy = t_acq + t_mcu + row.time_on_air_s
    if s.interval_s < busy:
        raise SDTError(
            f"interval {s.interval_s:g} s is shorter than one acquisition ({t_acq:g} s) plus its "
            f"computation and transmission ({t_mcu + row.time_on_air_s:.3g} s); lengthen --interval"
        )
    if row.duty_cycle_ok is False:
        raise SDTError(
            f"interval {s.interval_s:g} s breaks the {s.region.upper()} duty cycle at "
            f"{row.data_rate} (reports at most every {row.min_interval_s:.1f} s); "
            f"lengthen --interval"
        )
    if row.dwell_ok is False:
        raise SDTError(
            f"{row.data_rate} uplinks of {row.longest_message_s:.3f} s exceed the dwell time; "
            f"choose a faster --dr"
        )
    model = budget.radio
    stages = [
        Stage("accelerometer measuring", i_meas * 1e-6, t_acq, i_meas * 1e-6 * t_acq, meas_src),
        Stage(
            "accelerometer standby",
            None if i_stby is None else i_stby * 1e-6,
            s.interval_s - t_acq,
            None if i_stby is None else i_stby * 1e-6 * (s.interval_s - t_acq),
            stby_src,
        ),
        Stage(
            "microcontroller features",
            s.mcu_current_a,
            t_mcu,
            None if s.mcu_current_a is None else s.mcu_current_a * t_mcu,
            mcu_src,
            "" if s.mcu_current_a is not None else "run current not known: give --mcu-current-ma",
        ),
        Stage(f"radio transmit ({row.data_rate})", model.tx_current_a, row.time_on_air_s,
              model.tx_current_a * row.time_on_air_s, model.source or model.name),
        Stage("radio RX1", s.rx_current_a, t_rx1, s.rx_current_a * t_rx1,
              f"{nd.RX_SOURCE}; {s.rx_symbols} symbols at SF{rate.sf}"),
        Stage("radio RX2", s.rx_current_a, t_rx2, s.rx_current_a * t_rx2,
              f"{nd.RX_SOURCE}; {s.rx_symbols} symbols at SF{rx2_sf}/{rx2_bw / 1e3:g} kHz"),
    ]  # fmt: skip
    awake = t_mcu + row.time_on_air_s + t_rx1 + t_rx2
    stages.append(
        Stage("node sleep", s.sleep_current_a, s.interval_s - awake,
              s.sleep_current_a * (s.interval_s - awake), nd.SLEEP_SOURCE)
    )  # fmt: skip
    for stage in stages:
        if stage.charge_c is None:
            notes.append(f"{stage.consumer} not counted: {stage.note or stage.source}")
    if battery.self_discharge_per_year is None:
        notes.append(f"battery {battery.name}: self-discharge not known, not counted")
    charge = sum(st.charge_c for st in stages if st.charge_c is not None)
    average = charge / s.interval_s
    mode = sensor.supply.mode if sensor.supply is not None else ""
    return NodeBudget(
        sensor=sensor.name,
        sensor_mode=mode,
        battery=battery,
        region=budget.region,
        data_rate=row.data_rate,
        interval_s=s.interval_s,
        stages=tuple(stages),
        charge_per_report_c=charge,
        energy_per_report_j=charge * battery.voltage_v,
        average_current_a=average,
        life_years=life_years(average, battery),
        notes=tuple(notes),
    )


def battery_life_years(
    sensor: SensorSpec,
    feature_set: FeatureSetSpec,
    battery: Cell,
    settings: NodeSettings | None = None,
) -> float | None:
    """Years on ``battery`` for ``sensor`` (None when its supply current is not on record).

    The function ``sdt explore`` calls for its battery-life objective.
    """
    if sensor.supply is None or sensor.supply.measure_ua.value is None:
        return None
    return node_budget(sensor, feature_set, battery, settings).life_years
