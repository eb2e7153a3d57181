"""The zone each sensor grades per machine and condition (issue 40, item 8).

"Condition X: reference zone B, sensor zone C" was computed by hand from
features.parquet; it is now a table. The expected cells are computed here from
the constructed windows: the median V_RMS per channel with numpy, its zone by
explicit comparisons with ISO 10816-3 group 2 rigid (1.4 / 2.8 / 4.5 mm/s),
the machine's grade from the channel with the largest median (ISO grades by
the highest bearing), and the share of that channel's windows in that zone.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from sdt_plugins.datasets.pump_rig import rig_machines

from sdt_framework.severity import assign_tables, condition_zones, paired_zones, zone_agreement

CUTS = (1.4, 2.8, 4.5)


def _zone(v: float) -> str:
    return "ABCD"[int(np.select([v <= CUTS[0], v <= CUTS[1], v <= CUTS[2]], [0, 1, 2], 3))]


@pytest.fixture(scope="module")
def features() -> pd.DataFrame:
    """Motor-4, ch1 and ch4, healthy (2 runs) and 'cavitation' levels 1 and 2, 9 windows each.

    The sensor 'noisy' reads the reference plus 0.9 mm/s on ch4 only.
    """
    gen = np.random.default_rng(11)
    level = {
        ("healthy", None): (1.2, 2.2),
        ("cavitation", 1): (2.0, 3.1),
        ("cavitation", 2): (2.4, 5.0),
    }
    rows = []
    for (condition, severity), centres in level.items():
        for run in range(2 if condition == "healthy" else 1):
            for channel, centre in zip(("ch1", "ch4"), centres, strict=True):
                values = centre * np.exp(gen.normal(0, 0.15, 9))
                name = f"{condition} {run if severity is None else severity}"
                for sensor, extra in (("ref", 0.0), ("noisy", 0.9 if channel == "ch4" else 0.0)):
                    for w, v in enumerate(values):
                        rows.append(
                            {
                                "machine": "Motor-4",
                                "run": name,
                                "condition": condition,
                                "severity": severity,
                                "channel": channel,
                                "recording_id": f"{name}/{channel}",
                                "sensor": sensor,
                                "repeat": 0,
                                "acquisition": 0,
                                "window": w,
                                "V_RMS": v + extra,
                            }
                        )
    return pd.DataFrame(rows).astype({"severity": "Int64"})


def _expected(features: pd.DataFrame, sensor: str, condition: str, level) -> tuple:
    mine = features[(features["sensor"] == sensor) & (features["condition"] == condition)]
    mine = mine[mine["severity"].isna()] if level is None else mine[mine["severity"] == level]
    medians = {c: float(np.median(g["V_RMS"])) for c, g in mine.groupby("channel")}
    worst = max(medians, key=medians.get)
    zone = _zone(medians[worst])
    windows = mine[mine["channel"] == worst]["V_RMS"]
    share = float(np.mean([_zone(v) == zone for v in windows]))
    return worst, medians[worst], zone, share


def test_the_zone_per_condition_is_the_worst_channels_median(features) -> None:
    assignments = assign_tables(["Motor-4"], specs=rig_machines())
    table = condition_zones(paired_zones(features, "ref", assignments), "ref", assignments)
    machine = table[table["channel"] == "all"]
    assert len(machine) == 3 * 2  # three condition-levels, two sensors
    for condition, level in (("healthy", None), ("cavitation", 1), ("cavitation", 2)):
        for sensor in ("ref", "noisy"):
            rows = machine[(machine["condition"] == condition) & (machine["sensor"] == sensor)]
            row = (
                rows[rows["severity"].isna()] if level is None else rows[rows["severity"] == level]
            )
            worst, median, zone, share = _expected(features, sensor, condition, level)
            assert row["from_channel"].item() == worst
            assert row["v_rms"].item() == pytest.approx(median)
            assert row["zone"].item() == zone and row["share"].item() == pytest.approx(share)
    # per channel too: the noisy sensor's ch1 reads the reference's ch1
    ch1 = table[(table["channel"] == "ch1") & (table["condition"] == "healthy")]
    assert ch1["v_rms"].nunique() == 1


def test_the_agreement_carries_the_table_and_the_noisy_sensor_grades_worse(features) -> None:
    agreement = zone_agreement(
        features, "ref", assign_tables(["Motor-4"], specs=rig_machines()), n_boot=100
    )
    machine = agreement.conditions[agreement.conditions["channel"] == "all"]
    healthy = machine[machine["condition"] == "healthy"].set_index("sensor")["zone"]
    ref_zone = _expected(features, "ref", "healthy", None)[2]
    noisy_zone = _expected(features, "noisy", "healthy", None)[2]
    assert (healthy["ref"], healthy["noisy"]) == (ref_zone, noisy_zone)
    assert ref_zone < noisy_zone  # the construction puts 0.9 mm/s on the noisy ch4
