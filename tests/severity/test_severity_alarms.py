"""Criterion II alarms: each sensor on its own baseline, decreases counted (issue 40, item 4).

Features are built here with values chosen away from the thresholds, and the
expected alarm bits are computed in the test from the rule as ISO 10816-3:2009
5.3 and 5.4.1 state it (transcription in docs/severity.md): a change from the
measuring point's own baseline greater than 0.25 x B/C, in either direction;
ALARM = min(baseline + 0.25 x B/C, 1.25 x B/C). Table: ISO 10816-3 group 2
rigid (B/C 2.8 mm/s, so a significant change is 0.7 mm/s).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from sdt_plugins.datasets.pump_rig import rig_machines

from sdt_framework.severity import assign_tables, zone_agreement

B_C = 2.8
CHANGE = 0.25 * B_C  # 0.7 mm/s
BASELINE = 2.0  # the reference's healthy V_RMS: ALARM 2.7, a decrease below 1.3
# fault windows of the reference: 2.5 (a change of +0.5: no alarm), 3.2 (+1.2: alarm),
# 1.0 (-1.0: a decrease, alarm), 2.2 (+0.2: none); a x1.1 node's change is 1.1 x these,
# never within a factor 1.1 of 0.7, so on its own baseline it alarms exactly as the
# reference does
FAULT = (2.5, 3.2, 1.0, 2.2)
GAIN = 1.1


def _features() -> pd.DataFrame:
    rows = []
    runs = [("healthy", None, v) for v in (BASELINE,) * 4] + [("fault", 1, v) for v in FAULT]
    for k, (condition, level, value) in enumerate(runs):
        for sensor, gain in (("ref", 1.0), ("plus10", GAIN)):
            for w in range(3):
                rows.append(
                    {
                        "machine": "Motor-4",
                        "run": f"{condition} {k}",
                        "condition": condition,
                        "severity": level,
                        "channel": "ch1",
                        "recording_id": f"{condition} {k}/ch1",
                        "sensor": sensor,
                        "repeat": 0,
                        "acquisition": 0,
                        "window": w,
                        "V_RMS": gain * value,
                    }
                )
    return pd.DataFrame(rows).astype({"severity": "Int64"})


def _bits(values: np.ndarray, baseline: float) -> np.ndarray:
    alarm = min(baseline + CHANGE, 1.25 * B_C)
    return (values > alarm) | (values < baseline - CHANGE)


@pytest.fixture(scope="module")
def row() -> pd.Series:
    result = zone_agreement(
        _features(), "ref", assign_tables(["Motor-4"], specs=rig_machines()), n_boot=200
    )
    alarms = result.alarms
    return alarms[(alarms["sensor"] == "plus10") & (alarms["channel"] == "ch1")].iloc[0]


def test_a_plus_10_percent_node_alarms_exactly_with_the_reference_on_its_own_baseline(row):
    fault = np.repeat(FAULT, 3)
    reference = _bits(fault, BASELINE)
    own = _bits(GAIN * fault, GAIN * BASELINE)
    assert np.array_equal(reference, own)  # the construction is what it says
    assert row["baseline"] == pytest.approx(GAIN * BASELINE)
    assert row["alarm"] == pytest.approx(GAIN * BASELINE + CHANGE)
    assert row["fault_alarm_same"] == 1.0 and row["missed"] == 0.0
    assert row["false_alarm_sensor"] == 0.0


def test_on_the_reference_baseline_the_gain_error_becomes_an_alarm_disagreement(row):
    fault = np.repeat(FAULT, 3)
    refbase = _bits(GAIN * fault, BASELINE)  # 2.5 x 1.1 = 2.75 > ALARM 2.7
    expected = (refbase == _bits(fault, BASELINE)).mean()
    assert expected == pytest.approx(0.75)
    assert row["alarm_ref"] == pytest.approx(BASELINE + CHANGE)
    assert row["fault_alarm_same_refbase"] == pytest.approx(expected)


def test_a_decrease_beyond_a_quarter_of_b_c_is_an_alarm(row):
    # of the four fault runs, 3.2 rises and 1.0 falls by more than 0.7 mm/s
    assert row["fault_alarm_ref"] == pytest.approx(2 / 4)
    assert row["fault_alarm_sensor"] == pytest.approx(2 / 4)
