"""The daily budget of a node that sends one feature vector per reporting interval.

For a feature set with n features of b bytes each, on ``axes`` axes, one report
(one window's features) is P = n x b x axes application bytes (paper8, float32,
3 axes: 8 x 4 x 3 = 96 B). Per data rate of a regional plan, with N the largest
application payload (:mod:`.lorawan`):

- messages per report k = ceil(P / N): 1 when the report fits; otherwise it is
  split over k uplinks of at most N bytes (no fragmentation header counted);
- time on air per report: the sum of each uplink's T_packet (:mod:`.lora`) for
  its PHY payload, application bytes + 13;
- reports per day R = 86400 s / interval; messages per day k R; airtime per
  day T_report R; transmit fraction = airtime per day / 86400 s;
- duty cycle (EU868, 1 %): the LoRaWAN off time after an uplink is
  T_off = T_packet / d - T_packet, so reports can follow each other at best
  every T_report / d on one sub-band; a shorter interval breaks the rule;
- dwell time (US915 125 kHz channels): each uplink must stay under 400 ms;
- energy per report and per day: I_tx x V x airtime (:mod:`.energy`), the radio's
  transmit energy only.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from numbers import Integral

from ..errors import SDTError, shown
from ..specs import FeatureSetSpec
from .energy import DEFAULT_RADIO, Radio, energy_per_message_j
from .energy import radio as radio_named
from .lora import time_on_air_s
from .lorawan import OVERHEAD_BYTES, DataRate, Region, phy_payload_bytes
from .lorawan import region as region_named

__all__ = ["SECONDS_PER_DAY", "DataRateBudget", "EdgeBudget", "edge_budget", "report_bytes"]

SECONDS_PER_DAY = 86400.0


def report_bytes(feature_set: FeatureSetSpec, axes: int = 1, dtype: str | None = None) -> int:
    """Application payload of one report: bytes per window per axis x axes.

    ``dtype`` ("float16"/"float32") overrides the feature set's declared dtype.
    """
    if not (isinstance(axes, Integral) and axes >= 1):
        raise SDTError(f"axes must be a whole number >= 1, got {shown(axes)}")
    spec = feature_set if dtype is None else feature_set.with_dtype(dtype)
    return spec.bytes_per_window * axes


@dataclass(frozen=True)
class DataRateBudget:
    """What one report and one day cost at one data rate (see the module notes)."""

    data_rate: str
    modulation: str
    max_app_payload: int
    fits: bool
    messages_per_report: int
    time_on_air_s: float
    longest_message_s: float
    dwell_ok: bool | None
    messages_per_day: float
    airtime_per_day_s: float
    transmit_fraction: float
    min_interval_s: float | None
    duty_cycle_ok: bool | None
    energy_per_report_j: float
    energy_per_day_j: float


@dataclass(frozen=True)
class EdgeBudget:
    """The budget of one node profile over every LoRa data rate of a region."""

    feature_set: str
    n_features: int
    dtypes: tuple[str, ...]
    bytes_per_window_per_axis: int
    axes: int
    app_payload_bytes: int
    overhead_bytes: int
    interval_s: float
    reports_per_day: float
    region: str
    duty_cycle: float | None
    repeater: bool
    radio: Radio
    rows: tuple[DataRateBudget, ...]

    def to_dict(self) -> dict:
        """JSON-ready form."""
        return asdict(self)

    def fitting(self) -> list[DataRateBudget]:
        """Data rates whose single uplink holds the whole report."""
        return [row for row in self.rows if row.fits]


def _row(
    rate: DataRate, region: Region, app_bytes: int, interval_s: float, model: Radio, repeater: bool
) -> DataRateBudget:
    cap = rate.max_app_payload(repeater=repeater)
    k = max(1, math.ceil(app_bytes / cap))
    # k - 1 full messages of `cap` bytes and one of the rest: two airtimes, whatever k
    # (a million axes is 2.6 million messages at DR0, timed one by one in 11 s before)
    full, last = (
        time_on_air_s(
            phy_payload_bytes(size), rate.sf, rate.bandwidth_hz,
            preamble_symbols=region.preamble_symbols,
        )
        for size in (cap, app_bytes - cap * (k - 1))
    )  # fmt: skip
    t_report = (k - 1) * full + last
    longest = max(full, last) if k > 1 else last
    per_day = SECONDS_PER_DAY / interval_s
    airtime_day = t_report * per_day
    min_interval = None if region.duty_cycle is None else t_report / region.duty_cycle
    e_report = energy_per_message_j(t_report, model)
    return DataRateBudget(
        data_rate=rate.name,
        modulation=rate.label,
        max_app_payload=cap,
        fits=k == 1,
        messages_per_report=k,
        time_on_air_s=t_report,
        longest_message_s=longest,
        dwell_ok=None if rate.dwell_time_s is None else longest <= rate.dwell_time_s,
        messages_per_day=k * per_day,
        airtime_per_day_s=airtime_day,
        transmit_fraction=airtime_day / SECONDS_PER_DAY,
        min_interval_s=min_interval,
        duty_cycle_ok=None if min_interval is None else interval_s >= min_interval,
        energy_per_report_j=e_report,
        energy_per_day_j=e_report * per_day,
    )


def edge_budget(
    feature_set: FeatureSetSpec,
    *,
    axes: int = 3,
    interval_s: float = 600.0,
    region: str | Region = "EU868",
    radio: str | Radio = DEFAULT_RADIO,
    dtype: str | None = None,
    repeater: bool = True,
) -> EdgeBudget:
    """Payload, airtime, duty cycle and energy of one report per interval, per data rate.

    Parameters
    ----------
    feature_set
        What each report carries (one window's features per axis).
    axes
        Axes reported per node (3 for a triaxial accelerometer).
    interval_s
        Time between reports, s (``interval.parse_interval("10min")``).
    region
        Regional plan name ("EU868", "US915") or a :class:`Region`.
    radio
        Built-in radio name or a :class:`Radio` with your own current and voltage.
    dtype
        Override the feature set's dtype ("float16" halves a float32 payload).
    repeater
        Use the repeater-compatible payload limits (the conservative table).
    """
    if not (math.isfinite(interval_s) and interval_s > 0):
        raise SDTError(f"interval must be > 0 s, got {shown(interval_s)}")
    spec = feature_set if dtype is None else feature_set.with_dtype(dtype)
    plan = region if isinstance(region, Region) else region_named(region)
    model = radio if isinstance(radio, Radio) else radio_named(radio)
    app_bytes = report_bytes(spec, axes)
    return EdgeBudget(
        feature_set=spec.name,
        n_features=len(spec.feature_names),
        dtypes=tuple(sorted(set(spec.value_dtypes))),
        bytes_per_window_per_axis=spec.bytes_per_window,
        axes=axes,
        app_payload_bytes=app_bytes,
        overhead_bytes=OVERHEAD_BYTES,
        interval_s=float(interval_s),
        reports_per_day=SECONDS_PER_DAY / interval_s,
        region=plan.name,
        duty_cycle=plan.duty_cycle,
        repeater=repeater,
        radio=model,
        rows=tuple(
            _row(rate, plan, app_bytes, interval_s, model, repeater) for rate in plan.data_rates
        ),
    )
