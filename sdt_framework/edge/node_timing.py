"""When a node is busy in one reporting interval, and whether the interval allows it.

One report: the accelerometer turns on and records a window of W seconds on
every axis, the microcontroller computes the features (the feature set's
``node_ffts`` FFTs of the window per axis, :func:`fft_time_s`, plus, for a set
in orders of the running speed, one FFT zero-padded ``node_speed_pad`` times on
one axis: the tachless speed estimate), the radio sends the report in k uplinks of the
chosen data rate (k > 1 when the report is larger than the rate's payload
limit) and listens in RX1 and RX2 after each uplink. :func:`node_timing`
gives those times and refuses an interval the node cannot keep: shorter than
the acquisition plus computation plus transmission, or breaking the region's
duty cycle (:class:`IntervalError`, whose ``problem`` callers word for their
own option: ``--interval`` in ``sdt budget``, ``report_interval`` in a sweep).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import SDTError
from ..specs import FeatureSetSpec
from . import node_defaults as nd
from .budget import DataRateBudget, edge_budget
from .energy import Radio
from .lora import symbol_time_s
from .lorawan import DataRate
from .lorawan import region as region_named

__all__ = ["IntervalError", "Timing", "fft_time_s", "node_timing", "pick_rate"]


class IntervalError(SDTError):
    """A reporting interval the node cannot keep; ``problem`` says why, without the remedy."""

    def __init__(self, problem: str, remedy: str = "lengthen --interval") -> None:
        super().__init__(f"{problem}; {remedy}")
        self.problem = problem
        self.remedy = remedy


@dataclass(frozen=True)
class Timing:
    """The times of one report (s) and the data rate it goes at."""

    region: str
    row: DataRateBudget
    rate: DataRate
    radio: Radio
    samples: int
    t_on: float
    t_acq: float
    t_mcu: float
    uplinks: int
    t_rx1: float
    t_rx2: float
    rx2_sf: int
    rx2_bw: float
    #: the feature set's FFTs of the window per axis, and its speed estimate's zero-padding
    ffts: int = 1
    speed_pad: int = 0


def fft_time_s(samples: int, clock_hz: float = nd.MCU_CLOCK_HZ) -> float:
    """The reference FFT's cycles scaled by N log2 N, run at ``clock_hz``."""
    points, seconds, _, reference_hz = nd.FFT_REFERENCE
    n = max(samples, 2)
    cycles = seconds * reference_hz * n * math.log2(n) / (points * math.log2(points))
    return cycles / clock_hz


def pick_rate(rows: tuple[DataRateBudget, ...], wanted: str | None) -> DataRateBudget:
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


def node_timing(
    rate_hz: float,
    turn_on_s: float,
    feature_set: FeatureSetSpec,
    settings,  # NodeSettings (node.py imports this module)
) -> Timing:
    """The times of one report at ``settings``; :class:`IntervalError` when they do not fit."""
    s = settings
    budget = edge_budget(
        feature_set, axes=s.axes, interval_s=s.interval_s, region=s.region, radio=s.radio,
        repeater=s.repeater,
    )  # fmt: skip
    row = pick_rate(budget.rows, s.data_rate)
    plan = region_named(s.region)
    rate = next(r for r in plan.data_rates if r.name == row.data_rate)
    samples = max(1, round(s.window_s * rate_hz))
    ffts, pad = feature_set.node_ffts, feature_set.node_speed_pad
    speed_s = fft_time_s(pad * samples) if pad else 0.0  # the tachless estimate, one axis
    t_mcu = s.mcu_time_s if s.mcu_time_s is not None else s.axes * ffts * fft_time_s(samples)
    if s.mcu_time_s is None:
        t_mcu += speed_s
    t_acq = turn_on_s + s.window_s
    rx1_bw = 500e3 if plan.name == "US915" else 125e3
    t_rx1 = s.rx_symbols * symbol_time_s(rate.sf, rx1_bw)
    rx2_sf, rx2_bw = nd.RX2_MODULATION[plan.name]
    rx2_sf = s.rx2_sf or rx2_sf
    t_rx2 = s.rx_symbols * symbol_time_s(rx2_sf, rx2_bw)
    busy = t_acq + t_mcu + row.time_on_air_s
    if s.interval_s < busy:
        raise IntervalError(
            f"interval {s.interval_s:g} s is shorter than one acquisition ({t_acq:g} s) plus its "
            f"computation and transmission ({t_mcu + row.time_on_air_s:.3g} s)"
        )
    if row.duty_cycle_ok is False:
        raise IntervalError(
            f"interval {s.interval_s:g} s breaks the {plan.name} duty cycle at {row.data_rate} "
            f"(reports at most every {row.min_interval_s:.1f} s)"
        )
    if row.dwell_ok is False:
        raise SDTError(
            f"{row.data_rate} uplinks of {row.longest_message_s:.3f} s exceed the dwell time; "
            f"choose a faster --dr"
        )
    return Timing(
        plan.name, row, rate, budget.radio, samples, turn_on_s, t_acq, t_mcu,
        row.messages_per_report, t_rx1, t_rx2, rx2_sf, rx2_bw, ffts, pad,
    )  # fmt: skip
