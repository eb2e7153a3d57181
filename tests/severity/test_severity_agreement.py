"""Zone and alarm agreement against an independent computation on constructed features.

The features table is built here (V_RMS per window, as features.parquet holds
it), written to Parquet and read back; the expected figures are computed in
the test from the table's boundaries with plain comparisons, not by the code
under test.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from sdt_plugins.datasets.pump_rig import rig_machines

from sdt_framework.severity import assign_tables, zone_agreement

CUTS = (1.4, 2.8, 4.5)  # ISO 10816-3 group 2 rigid, the default for Motor-4


def _zone(v: np.ndarray) -> np.ndarray:
    """Zone 0-3 by explicit comparisons: A up to 1.4 (included), B to 2.8, C to 4.5, D above."""
    return np.select([v <= CUTS[0], v <= CUTS[1], v <= CUTS[2]], [0, 1, 2], default=3)


@pytest.fixture
def features(tmp_path: Path) -> pd.DataFrame:
    """Motor-4, 2 channels, 3 healthy runs and 2 faults x 2 levels, 8 windows per recording.

    The reference's V_RMS is log-uniform over 0.3-9 mm/s; sensor 'same' reads it
    exactly, sensor 'double' reads twice it (a chain with a gain of 2).
    """
    gen = np.random.default_rng(7)
    runs = [("healthy", None, f"healthy {k}") for k in (1, 2, 3)]
    runs += [(c, s, f"{c} {s}") for c in ("unbalance motor", "coupling") for s in (1, 2)]
    rows = []
    for condition, severity, run in runs:
        for channel in ("ch1", "ch2"):
            v = np.exp(gen.uniform(np.log(0.3), np.log(9.0), 8))
            for sensor, gain in (("ref", 1.0), ("same", 1.0), ("double", 2.0)):
                for w, value in enumerate(v):
                    rows.append(
                        {
                            "machine": "Motor-4",
                            "run": run,
                            "condition": condition,
                            "severity": severity,
                            "channel": channel,
                            "recording_id": f"{run}/{channel}",
                            "sensor": sensor,
                            "repeat": 0,
                            "acquisition": 0,
                            "window": w,
                            "V_RMS": np.float32(gain * value),
                        }
                    )
    frame = pd.DataFrame(rows).astype({"severity": "Int64"})
    frame.to_parquet(tmp_path / "features.parquet")
    return pd.read_parquet(tmp_path / "features.parquet")


def _agreement(features: pd.DataFrame):
    return zone_agreement(
        features, "ref", assign_tables(["Motor-4"], specs=rig_machines()), n_boot=500
    )


def test_a_sensor_identical_to_the_reference_agrees_on_every_window(features) -> None:
    result = _agreement(features)
    same = result.zones[result.zones["sensor"] == "same"]
    assert (same["share_same"] == 1.0).all() and (same["share_better"] == 0.0).all()
    assert (same["ci_low"] == 1.0).all() and (same["ci_high"] == 1.0).all()
    alarms = result.alarms[result.alarms["sensor"] == "same"]
    assert (alarms["fault_alarm_same"] == 1.0).all() and (alarms["missed"] == 0.0).all()
    assert (alarms["false_alarm_sensor"] == alarms["false_alarm_ref"]).all()


def test_a_gain_of_two_moves_exactly_the_windows_within_a_factor_2_below_a_boundary(
    features,
) -> None:
    ref = features[features["sensor"] == "ref"].sort_values(["recording_id", "window"])
    v = ref["V_RMS"].to_numpy(np.float64)
    doubled = features[features["sensor"] == "double"].sort_values(["recording_id", "window"])
    v2 = doubled["V_RMS"].to_numpy(np.float64)
    # prediction: a window changes zone iff a boundary c lies in [v, 2v), i.e. c/2 < v <= c,
    # and it moves up by the number of such boundaries
    cuts = np.array(CUTS)
    crossed = ((cuts / 2 < v[:, None]) & (v[:, None] <= cuts)).sum(axis=1)
    assert np.array_equal(_zone(v2) - _zone(v), crossed)  # the construction is what it says
    result = _agreement(features)
    pooled = result.zones[(result.zones["sensor"] == "double") & (result.zones["channel"] == "all")]
    assert pooled["share_same"].item() == pytest.approx(np.mean(crossed == 0))
    assert pooled["share_worse"].item() == pytest.approx(np.mean(crossed > 0))
    assert pooled["share_better"].item() == 0.0
    low, high = pooled["ci_low"].item(), pooled["ci_high"].item()
    assert low <= pooled["share_same"].item() <= high
    for channel in ("ch1", "ch2"):
        mine = (ref["channel"] == channel).to_numpy()
        row = result.zones[
            (result.zones["sensor"] == "double") & (result.zones["channel"] == channel)
        ]
        assert row["share_same"].item() == pytest.approx(np.mean(crossed[mine] == 0))
    conf = result.confusion
    part = conf[(conf["sensor"] == "double") & (conf["channel"] == "all")]
    expected = pd.crosstab(_zone(v), _zone(v2)).stack()
    got = part.set_index(["reference_zone", "sensor_zone"])["count"]
    letters = {i: "ABCD"[i] for i in range(4)}
    for (i, j), count in expected.items():
        assert got[(letters[i], letters[j])] == count
    assert got.sum() == len(v)


def test_alarm_thresholds_follow_criterion_ii_on_each_sensors_own_baseline(features) -> None:
    result = _agreement(features)
    for channel in ("ch1", "ch2"):
        at = features[features["channel"] == channel]
        ref, double = at[at["sensor"] == "ref"], at[at["sensor"] == "double"]
        healthy = ref[ref["severity"].isna()]["V_RMS"].to_numpy(np.float64)
        own = double[double["severity"].isna()]["V_RMS"].to_numpy(np.float64)
        alarm_ref = min(healthy.mean() + 0.25 * 2.8, 1.25 * 2.8)
        alarm_own = min(own.mean() + 0.25 * 2.8, 1.25 * 2.8)
        row = result.alarms[
            (result.alarms["sensor"] == "double") & (result.alarms["channel"] == channel)
        ]
        assert row["alarm"].item() == pytest.approx(alarm_own)
        assert row["alarm_ref"].item() == pytest.approx(alarm_ref)  # kept beside, named
        assert row["capped"].item() == (own.mean() + 0.7 > 3.5)
        assert row["trip"].item() == pytest.approx(1.25 * 4.5)
        # the bit: above ALARM, or a decrease of more than 0.25 x B/C below the baseline
        fault_ref = ref[ref["severity"].notna()]["V_RMS"].to_numpy(np.float64)
        fault_own = double[double["severity"].notna()]["V_RMS"].to_numpy(np.float64)
        bit_ref = (fault_ref > alarm_ref) | (fault_ref < healthy.mean() - 0.7)
        bit_own = (fault_own > alarm_own) | (fault_own < own.mean() - 0.7)
        bit_refbase = (fault_own > alarm_ref) | (fault_own < healthy.mean() - 0.7)
        assert row["fault_alarm_ref"].item() == pytest.approx(bit_ref.mean())
        assert row["fault_alarm_same"].item() == pytest.approx((bit_ref == bit_own).mean())
        assert row["fault_alarm_same_refbase"].item() == pytest.approx(
            (bit_ref == bit_refbase).mean()
        )
        false_own = (own > alarm_own) | (own < own.mean() - 0.7)
        assert row["false_alarm_sensor"].item() == pytest.approx(false_own.mean())


def test_the_report_section_shows_the_table_used_and_the_agreement(features, tmp_path) -> None:
    from sdt_framework.report.document import Table
    from sdt_framework.report.load import ResultsFolder
    from sdt_framework.report.severity import severity_blocks

    results = pd.DataFrame(
        columns=["machine", "scenario", "sensor", "classifier", "macro_f1", "status"]
    )
    from sdt_framework.report.machines import FolderMachines

    folder = ResultsFolder(tmp_path, results, features=features)
    folder.summary = {"reference": "ref"}
    folder.machines = FolderMachines(rig_machines())  # the pump rig's, as its datasets give
    blocks = severity_blocks(folder, None, tmp_path / "figures", {})
    tables = [b for b in blocks if isinstance(b, Table)]
    used = tables[0].rows[0]
    assert used[:3] == ("Motor-4", "iso10816-3-group2-rigid", "1.4 / 2.8 / 4.5")
    assert "ISO 10816-3:2009" in used[3] and "Table A.2" in used[3]
    agreement = {(r[1], r[2]): r[4] for r in tables[1].rows}
    assert agreement[("all", "same")] == "100.0 %"
    assert blocks[-1].text.startswith("Not drawn: config.toml")  # no dataset to re-open
