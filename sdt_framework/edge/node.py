"""The whole node's charge per report, one stage per consumer, and the battery's life.

Every reporting interval T the node wakes its accelerometer, records one
window of W seconds on every axis while the microcontroller serves the
accelerometer's FIFO, computes the features, sends the report in k LoRaWAN
class A uplinks (k = 1 when it fits one) and listens in RX1 and RX2 after
each, and sleeps the rest of the time; its regulator draws its quiescent
current throughout. Per report, with I the supply current of each consumer
(A) and t its time (s) (:mod:`.node_timing`):

    accelerometer measuring     Q = I_meas (t_on + W)
    accelerometer standby       Q = I_stby (T - t_on - W)
    microcontroller acquiring   Q = I_acq (t_on + W)        (awake serving the FIFO)
    microcontroller features    Q = I_mcu t_mcu,  t_mcu = axes F t_FFT(N) + t_FFT(P N)
    radio transmit              Q = I_tx ToA                (all k uplinks, :mod:`.lora`)
    radio RX1, RX2              Q = k I_rx n_sym T_sym(window's data rate)
    regulator quiescent         Q = I_q T
    node sleep                  Q = I_sleep (T - t_on - W - t_mcu - ToA - k (t_rx1 + t_rx2))

The charge per report is the sum; the average current is that over T; the
battery's life follows from :func:`.cells.cell_life` (capacity at that drain,
self-discharge, capped at the cell's shelf life). Every current is drawn from
the battery through a linear regulator, so the battery delivers the same
current; energy per report is charge x the cell's voltage. Each stage carries
its source (``node.toml`` via :mod:`.node_defaults`, the sensor's supply
figures, ``radios.toml``); a stage whose current is not known is listed as not
counted, never filled in, and every budget ends with what the model leaves out.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from numbers import Integral

from ..errors import SDTError, shown
from ..specs import FeatureSetSpec, SensorSpec
from . import node_defaults as nd
from .cells import Cell, cell_life
from .energy import NODE_RADIO, Radio
from .node_timing import node_timing

__all__ = ["NodeBudget", "NodeSettings", "Stage", "battery_life_years", "node_budget"]


@dataclass(frozen=True)
class NodeSettings:
    """What the node does besides its accelerometer; every default is sourced (node.toml).

    ``rx_current_a`` None takes the radio profile's receive current (else
    node.toml's); ``mcu_acquire_current_a`` None takes ``mcu_current_a``
    (awake through the window: the upper bound).
    """

    interval_s: float = 600.0
    window_s: float = 0.64
    axes: int = 3
    region: str = "EU868"
    data_rate: str | None = None
    radio: Radio | str = NODE_RADIO
    rx_current_a: float | None = None
    rx_symbols: int = nd.RX_SYMBOLS
    rx2_sf: int | None = None
    sleep_current_a: float = nd.SLEEP_CURRENT_A
    mcu_current_a: float | None = nd.MCU_CURRENT_A
    mcu_time_s: float | None = None
    mcu_acquire_current_a: float | None = None
    regulator_current_a: float = nd.REGULATOR_A
    repeater: bool = True

    def __post_init__(self) -> None:
        for name in ("interval_s", "window_s"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise SDTError(f"{name.removesuffix('_s')} must be > 0 s, got {shown(value)}")
        for name in (
            "rx_current_a", "sleep_current_a", "mcu_current_a", "mcu_time_s",
            "mcu_acquire_current_a", "regulator_current_a",
        ):  # fmt: skip
            value = getattr(self, name)
            if value is not None and not (math.isfinite(value) and value >= 0):
                unit = "s" if name.endswith("_s") else "A"
                raise SDTError(f"{name} must be >= 0 {unit}, got {shown(value)}")
        if not (isinstance(self.rx_symbols, Integral) and self.rx_symbols >= 0):
            raise SDTError(
                f"receive window must be a whole number of symbols, got {shown(self.rx_symbols)}"
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
    """A node's charge per report by consumer, average current and battery life.

    ``life_years`` is capped at the cell's shelf life (``life_capped`` says
    when); ``uncapped_life_years`` is what the drain alone would give.
    """

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
    life_capped: bool = False
    uncapped_life_years: float = math.nan
    capacity_mah: float = math.nan
    uplinks: int = 1
    radio: str = ""

    def to_dict(self) -> dict:
        """JSON-ready form."""
        data = asdict(self)
        inf = math.isinf(self.uncapped_life_years)
        data["uncapped_life_years"] = None if inf else self.uncapped_life_years
        data["battery"]["curve"] = [list(p) for p in self.battery.curve]
        return data


def _figure(sensor: SensorSpec, name: str) -> tuple[float | None, str]:
    supply = sensor.supply
    if supply is None:
        return None, f"{sensor.name} has no supply figures on record"
    figure = supply.figures()[name]
    return figure.value, figure.cited()


def _charge(current: float | None, time_s: float) -> float | None:
    return None if current is None else current * time_s


def node_budget(
    sensor: SensorSpec,
    feature_set: FeatureSetSpec,
    battery: Cell,
    settings: NodeSettings | None = None,
) -> NodeBudget:
    """Charge per report by consumer, average current and life of ``battery`` (module notes)."""
    s = settings or NodeSettings()
    notes: list[str] = []
    i_meas, meas_src = _figure(sensor, "measure_ua")
    i_stby, stby_src = _figure(sensor, "standby_ua")
    t_on_ms, on_src = _figure(sensor, "turn_on_ms")
    if i_meas is None:
        raise SDTError(
            f"sensor {sensor.name!r}: no measuring supply current ({meas_src}); "
            f"give it with --sensor-current-ua"
        )
    if t_on_ms is None:
        notes.append(f"turn-on time not counted ({on_src})")
    if sensor.sampling_rate_hz == "native":
        raise SDTError(f"sensor {sensor.name!r} samples at the recording's rate: no node to budget")
    t = node_timing(float(sensor.sampling_rate_hz), (t_on_ms or 0.0) / 1e3, feature_set, s)
    stages = _stages(s, t, i_meas * 1e-6, meas_src, i_stby, stby_src)
    for stage in stages:
        if stage.charge_c is None:
            notes.append(f"{stage.consumer} not counted: {stage.note or stage.source}")
    charge = sum(st.charge_c for st in stages if st.charge_c is not None)
    average = charge / s.interval_s
    life = cell_life(average, battery)
    if life.capped:
        notes.append(life.cap_note(battery))
    notes.append(nd.NOT_COUNTED)
    return NodeBudget(
        sensor=sensor.name,
        sensor_mode=sensor.supply.mode if sensor.supply is not None else "",
        battery=battery,
        region=t.region,
        data_rate=t.row.data_rate,
        interval_s=s.interval_s,
        stages=tuple(stages),
        charge_per_report_c=charge,
        energy_per_report_j=charge * battery.voltage_v,
        average_current_a=average,
        life_years=life.years,
        notes=tuple(notes),
        life_capped=life.capped,
        uncapped_life_years=life.uncapped_years,
        capacity_mah=life.capacity_mah,
        uplinks=t.uplinks,
        radio=t.radio.name,
    )


def _ffts(t, axes: int) -> str:
    """``"2048 points x 3 axes"``; for a set in orders, its FFTs and the speed estimate's."""
    each = f"{t.samples} points x {axes} axes"
    if t.ffts > 1:
        each = f"{t.ffts} FFTs of {each}"
    if t.speed_pad:
        each += f" + one of {t.speed_pad * t.samples} points ({t.speed_pad}x zero-padded: speed)"
    return each


def _stages(s: NodeSettings, t, i_meas: float, meas_src: str, i_stby, stby_src: str) -> list[Stage]:
    """One :class:`Stage` per consumer, in the order of the module notes."""
    radio, k = t.radio, t.uplinks
    mcu_src = (
        "user setting"
        if s.mcu_time_s is not None
        else f"{nd.FFT_REFERENCE[2]}, scaled to {_ffts(t, s.axes)} at {nd.MCU_CLOCK_HZ / 1e6:g} MHz"
    )
    if s.mcu_current_a == nd.MCU_CURRENT_A:
        mcu_src += f"; current: {nd.MCU_SOURCE}"
    unknown_mcu = "run current not known: give --mcu-current-ma"
    i_acq = s.mcu_current_a if s.mcu_acquire_current_a is None else s.mcu_acquire_current_a
    acq_src = (
        "user setting"
        if s.mcu_acquire_current_a is not None
        else f"awake at its run current through turn-on and window, serving the FIFO (upper "
        f"bound; {nd.MCU_STOP2_A * 1e6:g} uA in Stop 2 between FIFO reads is the floor): "
        f"--mcu-acquire-ma"
    )
    i_rx = s.rx_current_a if s.rx_current_a is not None else radio.rx_current_a
    rx_src = "user setting" if s.rx_current_a is not None else radio.rx_source
    if i_rx is None:
        i_rx, rx_src = nd.RX_CURRENT_A, f"{nd.RX_SOURCE} (the profile gives no receive current)"
    per = f" x {k} uplinks" if k > 1 else ""
    rx1 = f"{rx_src}; {s.rx_symbols} symbols at SF{t.rate.sf}{per}"
    rx2 = f"{rx_src}; {s.rx_symbols} symbols at SF{t.rx2_sf}/{t.rx2_bw / 1e3:g} kHz{per}"
    reg_src = "user setting" if s.regulator_current_a != nd.REGULATOR_A else nd.REGULATOR_SOURCE
    toa, t_rx1, t_rx2 = t.row.time_on_air_s, k * t.t_rx1, k * t.t_rx2
    asleep = s.interval_s - t.t_acq - t.t_mcu - toa - t_rx1 - t_rx2
    i_stby_a = None if i_stby is None else i_stby * 1e-6
    return [
        Stage("accelerometer measuring", i_meas, t.t_acq, i_meas * t.t_acq, meas_src),
        Stage("accelerometer standby", i_stby_a, s.interval_s - t.t_acq,
              _charge(i_stby_a, s.interval_s - t.t_acq), stby_src),
        Stage("microcontroller acquiring", i_acq, t.t_acq, _charge(i_acq, t.t_acq), acq_src,
              "" if i_acq is not None else unknown_mcu),
        Stage("microcontroller features", s.mcu_current_a, t.t_mcu,
              _charge(s.mcu_current_a, t.t_mcu), mcu_src,
              "" if s.mcu_current_a is not None else unknown_mcu),
        Stage(f"radio transmit ({t.row.data_rate}{per})", radio.tx_current_a, toa,
              radio.tx_current_a * toa, f"{radio.name}: {radio.source or 'user setting'}"),
        Stage("radio RX1", i_rx, t_rx1, i_rx * t_rx1, rx1),
        Stage("radio RX2", i_rx, t_rx2, i_rx * t_rx2, rx2),
        Stage("regulator quiescent", s.regulator_current_a, s.interval_s,
              s.regulator_current_a * s.interval_s, reg_src),
        Stage("node sleep", s.sleep_current_a, asleep, s.sleep_current_a * asleep,
              nd.SLEEP_SOURCE),
    ]  # fmt: skip


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
