"""Criterion II alarms on each sensor's own baseline, with the reference's baseline beside it.

Criterion II is relative: each measuring point alarms on a change from its own
established baseline (``criterion2.toml``: ISO 10816-3:2009 5.3, 5.4.1, 5.4.2,
as transcribed). Per machine, channel and sensor, the sensor's healthy
windows set its baseline (mean V_RMS); its bit is raised on a window above
ALARM = min(baseline + 0.25 x B/C, 1.25 x B/C) or below baseline - 0.25 x B/C
(a decrease is a change too, 5.3), and TRIP is 1.25 x C/D. The reference's
bit uses the reference's own baseline. So a sensor with a gain error g alarms
when the reference does unless the window's change lies within a factor g of
0.25 x B/C: its offset is removed, its scale is not.

The same sensor windows judged on the *reference's* thresholds (what a node
commissioned with the reference's baseline would send) are kept beside, as
the ``*_refbase`` columns: there a gain error becomes an alarm disagreement.
"""

from __future__ import annotations

from dataclasses import dataclass
from importlib import resources

import numpy as np
import pandas as pd

from ..toml_files import parse_toml
from .tables import Assignment

__all__ = ["ALARM_FRACTION", "HEADROOM", "RULE", "CriterionII", "alarm_bits", "alarm_thresholds"]

_CHANNEL = ["machine", "channel"]
_WINDOW = ["machine", "channel", "recording_id", "acquisition", "window"]


@dataclass(frozen=True)
class CriterionII:
    """The change, ALARM and TRIP rules and the clauses that give them."""

    document: str
    edition: str
    clauses: tuple[str, str, str]  # change, ALARM, TRIP
    change_fraction: float  # a significant change, x B/C
    both_directions: bool
    alarm_fraction: float  # ALARM = baseline + this x B/C ...
    alarm_headroom: float  # ... at most this x B/C
    trip_headroom: float  # TRIP at most this x C/D

    @property
    def source(self) -> str:
        """Document, edition and clauses, as a citation."""
        return f"{self.document}:{self.edition.split(' ')[0]} {', '.join(self.clauses)}"


def _load() -> CriterionII:
    text = resources.files(__package__).joinpath("criterion2.toml").read_text(encoding="utf-8")
    data = parse_toml(text, "criterion2.toml")
    change, alarm, trip = data["change"], data["alarm"], data["trip"]
    return CriterionII(
        data["document"],
        data["edition"],
        (change["clause"], alarm["clause"], trip["clause"]),
        float(change["fraction_of_b_c"]),
        bool(change["both_directions"]),
        float(alarm["fraction_of_b_c"]),
        float(alarm["at_most_x_b_c"]),
        float(trip["at_most_x_c_d"]),
    )


#: the rules shipped in criterion2.toml
RULE = _load()
ALARM_FRACTION = RULE.alarm_fraction
HEADROOM = RULE.alarm_headroom


def _levels(baseline: pd.Series, b_c: pd.Series) -> dict[str, pd.Series]:
    """ALARM, whether it is capped (the baseline is already above B/C) and the drop threshold."""
    raw = baseline + RULE.alarm_fraction * b_c
    drop = baseline - RULE.change_fraction * b_c if RULE.both_directions else baseline * -np.inf
    return {
        "alarm": np.minimum(raw, RULE.alarm_headroom * b_c),
        "capped": raw > RULE.alarm_headroom * b_c,
        "drop": drop,
    }


def alarm_thresholds(pairs: pd.DataFrame, assignments: dict[str, Assignment]) -> pd.DataFrame:
    """Per machine, channel and sensor: thresholds on the sensor's own and the reference's baseline.

    Columns: ``baseline``, ``alarm``, ``capped``, ``drop`` (the decrease
    threshold) from the sensor's healthy windows; ``baseline_ref``,
    ``alarm_ref``, ``capped_ref``, ``drop_ref`` from the reference's; ``trip``.
    A channel without healthy windows has no baseline (NaN: no change alarm).
    """
    healthy = pairs[pairs["healthy"]]
    ref = healthy.drop_duplicates(_WINDOW).groupby(_CHANNEL)["v_ref"].mean()
    own = healthy.groupby([*_CHANNEL, "sensor"])["v_sensor"].mean()
    base = pairs.groupby([*_CHANNEL, "sensor"]).size().rename("n").reset_index()
    base = base.merge(own.rename("baseline").reset_index(), how="left", on=[*_CHANNEL, "sensor"])
    base = base.merge(ref.rename("baseline_ref").reset_index(), how="left", on=_CHANNEL)
    # float: an empty mapped column keeps the machines' string dtype, which arithmetic refuses
    b_c = base["machine"].map(lambda m: assignments[m].table.boundaries.b_c).astype(float)
    c_d = base["machine"].map(lambda m: assignments[m].table.boundaries.c_d).astype(float)
    own_levels, ref_levels = _levels(base["baseline"], b_c), _levels(base["baseline_ref"], b_c)
    for name in ("alarm", "capped", "drop"):
        base[name], base[f"{name}_ref"] = own_levels[name], ref_levels[name]
    base["trip"] = RULE.trip_headroom * c_d
    return base.drop(columns="n")


def alarm_bits(pairs: pd.DataFrame) -> pd.DataFrame:
    """``pairs`` merged with its thresholds gains each window's bits.

    ``alarm_ref`` (the reference on its thresholds), ``alarm_sensor`` (the
    sensor on its own), ``alarm_sensor_refbase`` (the sensor on the
    reference's thresholds), and the ``*_same`` agreement of each with the
    reference's bit; ``trip_same`` for TRIP.
    """
    out = pairs.copy()
    v_ref, v_sensor = out["v_ref"], out["v_sensor"]
    out["bit_ref"] = (v_ref > out["alarm_ref"]) | (v_ref < out["drop_ref"])
    out["bit_sensor"] = (v_sensor > out["alarm"]) | (v_sensor < out["drop"])
    out["bit_refbase"] = (v_sensor > out["alarm_ref"]) | (v_sensor < out["drop_ref"])
    out["alarm_same"] = out["bit_ref"] == out["bit_sensor"]
    out["alarm_same_refbase"] = out["bit_ref"] == out["bit_refbase"]
    out["trip_same"] = (v_ref > out["trip"]) == (v_sensor > out["trip"])
    return out
