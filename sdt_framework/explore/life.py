"""Battery life of every design point: the constraint and objective beside Macro F1.

``min_battery_life_years = 5`` under a sweep's ``[sweep.target]`` asks that the
node built around a point last at least five years on its ``battery`` (2xAA by
default) sending one report per ``report_interval`` (10 min by default). The
life is the whole node's (:mod:`sdt_framework.edge.node`: the accelerometer
measuring and in standby, the microcontroller awake through the window and
its FFT of the point's window at its rate, the LoRaWAN uplink and receive
windows, the regulator, sleep), at the protocol's window length, computed from
the point's own sensor specification, capped at the cell's shelf life
(``life_note`` then says so). A point whose sensor has no measuring supply
current on record has no life: NaN, with the reason in ``life_note``, never a
figure filled in, so it cannot meet a life constraint. A ``report_interval``
no node can keep is refused before any run (:func:`check_report_interval`).
This module attaches the life to the exploration table, one value per point;
:mod:`.objectives` decides pass or fail.
"""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

from ..edge.cells import cell
from ..edge.life_objective import point_life
from ..edge.node import NodeSettings
from ..edge.node_timing import IntervalError, node_timing
from ..errors import SDTError
from ..specs import FeatureSetSpec, SensorSpec
from .target import Target

__all__ = ["check_report_interval", "point_lives", "with_battery_life"]


def check_report_interval(
    target: Target,
    sensors: Sequence[SensorSpec],
    feature_set: FeatureSetSpec,
    window_s: float,
    where: str,
) -> None:
    """Refuse, before any run, a ``report_interval`` no point's node can keep.

    Asked when the target wants a battery life or names the interval: an
    interval shorter than one acquisition plus its computation and uplink, or
    one that breaks the duty cycle, is one line naming the sweep file and
    ``sweep.target.report_interval``. Other reasons a point has no life (no
    supply current, a report no uplink carries) stay per point (``life_note``).
    """
    asked = target.min_battery_life_years is not None
    if not asked and "report_interval" not in target.model_fields_set:
        return
    settings = NodeSettings(interval_s=target.interval_s, window_s=window_s)
    for spec in sensors:
        if spec.sampling_rate_hz == "native":
            continue
        on = spec.supply.turn_on_ms.value if spec.supply is not None else None
        try:
            node_timing(float(spec.sampling_rate_hz), (on or 0.0) / 1e3, feature_set, settings)
        except IntervalError as exc:
            raise SDTError(
                f"{where}: sweep.target.report_interval = {target.report_interval!r}: "
                f"{exc.problem}; lengthen report_interval"
            ) from None
        except SDTError:
            continue


def point_lives(
    sensors: Sequence[SensorSpec], feature_set: FeatureSetSpec, window_s: float, target: Target
) -> pd.DataFrame:
    """``point``, ``battery_life_years`` (NaN when unknown) and ``life_note`` (why unknown).

    One row per sensor (a design point's, or the base's), on the target's
    battery and reporting interval, at the protocol's window ``window_s``.
    """
    settings = NodeSettings(interval_s=target.interval_s, window_s=window_s)
    battery = cell(target.battery)
    rows = []
    for spec in sensors:
        years, why = point_life(spec, feature_set, battery, settings)
        rows.append({"point": spec.name, "battery_life_years": years, "life_note": why})
    return pd.DataFrame(rows, columns=["point", "battery_life_years", "life_note"])


def with_battery_life(table: pd.DataFrame, lives: pd.DataFrame, target: Target) -> pd.DataFrame:
    """``table`` with each row's point's ``battery_life_years`` when ``target`` asks for it.

    ``lives`` is :func:`point_lives`'s table. The reference's row stays NaN:
    it is the instrument the points are compared with, never judged.
    """
    if target.min_battery_life_years is None:
        return table
    out = table.drop(columns="battery_life_years", errors="ignore")
    return out.merge(lives[["point", "battery_life_years"]], on="point", how="left")
