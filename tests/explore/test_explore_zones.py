"""Zone agreement as a sweep objective: constructed answers, the minimum specification, bad values.

Expected shares are counted in the test from the windows' V_RMS and the
zone table's boundaries with plain comparisons, not by the code under test.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from sdt_plugins.datasets.pump_rig import rig_machines
from typer.testing import CliRunner

from sdt_framework.cli.main import app
from sdt_framework.explore import min_spec
from sdt_framework.explore.minspec import meeting_points
from sdt_framework.explore.objectives import verdicts
from sdt_framework.explore.sweep import Target
from sdt_framework.explore.zones import point_zone_agreement
from sdt_framework.severity import assign_tables, builtin_tables

CUTS = (1.4, 2.8, 4.5)  # ISO 10816-3 group 2 rigid, the default table of Motor-4
#: reference V_RMS (mm/s) per window; x 1.5 moves the six between 0.94 and 4.5 one zone up
VALUES = np.array([0.5, 1.0, 1.2, 2.0, 2.5, 3.5, 4.0, 6.0])


def _zone(v: np.ndarray) -> np.ndarray:
    """Zone 0-3 by explicit comparisons: A up to 1.4 (included), B to 2.8, C to 4.5, D above."""
    return np.select([v <= CUTS[0], v <= CUTS[1], v <= CUTS[2]], [0, 1, 2], default=3)


def _features(gains: dict[str, float]) -> pd.DataFrame:
    """Motor-4, two channels, three recordings of VALUES; each sensor reads gain x V_RMS."""
    rows = []
    for run, condition, severity in [("h", "healthy", None), ("u1", "unbalance", 1)]:
        for channel in ("ch1", "ch2"):
            for sensor, gain in {"ref": 1.0, **gains}.items():
                for w, value in enumerate(VALUES):
                    rows.append(
                        {
                            "machine": "Motor-4",
                            "condition": condition,
                            "severity": severity,
                            "channel": channel,
                            "recording_id": f"{run}/{channel}",
                            "sensor": sensor,
                            "repeat": 0,
                            "acquisition": 0,
                            "window": w,
                            "V_RMS": gain * value,
                        }
                    )
    return pd.DataFrame(rows).astype({"severity": "Int64"})


def test_the_table_used_is_the_one_the_test_counts_with() -> None:
    table = builtin_tables()["iso10816-3-group2-rigid"]
    assert tuple(table.cuts) == CUTS
    assert assign_tables(["Motor-4"], specs=rig_machines())["Motor-4"].table.name == table.name


def test_identical_point_agrees_everywhere_and_a_scaled_one_as_counted_by_hand() -> None:
    features = _features({"same": 1.0, "scaled": 1.5})
    shares = point_zone_agreement(features, "ref", assign_tables(["Motor-4"], specs=rig_machines()))
    got = shares.set_index("point")["zone_agreement"]
    assert got["same"] == 1.0
    # by hand: 0.5 -> 0.75 (A, A) and 6.0 -> 9.0 (D, D) stay; the other six cross up
    assert got["scaled"] == 2 / 8
    assert got["scaled"] == np.mean(_zone(VALUES) == _zone(1.5 * VALUES))  # independent count
    assert set(shares["machine"]) == {"Motor-4"} and "ref" not in set(shares["point"])


def _tidy(shares: dict[float, float], f1: float = 0.9) -> pd.DataFrame:
    """One cell, points along the sampling rate, Macro F1 ``f1`` everywhere, given zone shares."""
    rows = [
        {"point": "ref", "role": "reference", "rate": np.nan, "macro_f1": 0.9, "zone": 1.0}
    ] + [{"point": f"r{r:g}", "role": "point", "rate": r, "macro_f1": f1, "zone": s}
         for r, s in shares.items()]  # fmt: skip
    frame = pd.DataFrame(rows).rename(columns={"rate": "sampling_rate_hz"})
    frame = frame.rename(columns={"zone": "zone_agreement"})
    return frame.assign(machine="Motor-4", scenario="forward", classifier="lr", repeat=0)


SHARES = {800.0: 0.80, 1600.0: 0.93, 3200.0: 0.96, 6400.0: 0.99}
FIELDS = ["sampling_rate_hz"]
DEMAND = {"sampling_rate_hz": "higher"}
BASE = {"sampling_rate_hz": 3200.0}


def test_adding_zone_agreement_moves_the_minimum_specification() -> None:
    table = _tidy(SHARES)
    f1_only = min_spec(table, FIELDS, BASE, Target(max_loss=0.05), DEMAND)
    both = min_spec(table, FIELDS, BASE, Target(max_loss=0.05, zone_agreement=0.95), DEMAND)
    assert f1_only["min_level"].tolist() == [800.0]  # every level reaches Macro F1
    assert "min_level_zones" not in f1_only
    # 0.96 and 0.99 reach 95 %, 0.93 does not: the least rate with every faster one passing
    assert both["min_level"].tolist() == [3200.0]
    assert both["min_level_macro_f1"].tolist() == [800.0]
    assert both["min_level_zones"].tolist() == [3200.0]
    assert both["target"].iloc[0] == "loss to reference <= 0.05 and zone agreement >= 0.95"


def test_a_point_meets_only_when_both_constraints_hold() -> None:
    table = _tidy(SHARES)
    table.loc[table["point"] == "r6400", "macro_f1"] = 0.5  # fails Macro F1, passes zones
    judged = verdicts(table, FIELDS, Target(max_loss=0.05, zone_agreement=0.95))
    by = judged.set_index("point")
    assert by.loc["r6400", ["meets_macro_f1", "meets_zones", "meets"]].tolist() == [
        False,
        True,
        False,
    ]
    assert by.loc["r1600", ["meets_macro_f1", "meets_zones", "meets"]].tolist() == [
        True,
        False,
        False,
    ]
    assert by["meets"].to_dict() == {"r800": False, "r1600": False, "r3200": True, "r6400": False}
    meeting = meeting_points(table, FIELDS, Target(max_loss=0.05, zone_agreement=0.95))
    assert meeting["point"].tolist() == ["r3200"]
    assert meeting["zone_agreement"].tolist() == [0.96]


def test_a_share_exactly_at_the_target_meets_it() -> None:
    judged = verdicts(_tidy({800.0: 0.95}), FIELDS, Target(max_loss=0.05, zone_agreement=0.95))
    assert judged["meets"].tolist() == [True]


SWEEP = """[sweep]
base = "adxl345"
[sweep.axes]
sampling_rate_hz = {{ levels = [800, 3200] }}
[sweep.ties]
digital_cutoff_hz = "rate / 2 - 1"
[sweep.target]
max_loss = 0.1
{zone}
[benchmark]
dataset_options = {{ duration = 1.5 }}
machines = ["Motor-2"]
channels = ["ch1", "ch4"]
classifiers = ["lr"]
scenarios = ["forward"]
repeats = 1
jobs = 1
report = false
{extra}"""


def _refused(sdt, sweep: Path, out: Path) -> list[str]:
    """``sdt explore`` on a bad sweep: exit 2, one ``error:`` line (returned), no traceback."""
    result = sdt("explore", str(sweep), "--out", str(out))
    assert result.returncode == 2, result.stderr
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), result.stderr
    return lines


@pytest.mark.parametrize("value", ["0", "1.5", "-0.2", '"most"'])
def test_a_bad_zone_agreement_is_one_line_naming_file_and_field(
    sdt_in_process, tmp_path, value
) -> None:
    path = tmp_path / "sweep.toml"
    path.write_text(SWEEP.format(zone=f"zone_agreement = {value}", extra=""))
    lines = _refused(sdt_in_process, path, tmp_path / "o")
    assert str(path) in lines[0] and "sweep.target.zone_agreement" in lines[0]


@pytest.mark.parametrize(
    ("zones", "message"),
    [
        ('{ "Motor-9" = "iso10816-3-group2-rigid" }', "Motor-9: no machine 'Motor-9' here"),
        ('{ "Motor-2" = "iso-nope" }', "Motor-2: unknown zone table 'iso-nope'"),
    ],
)
def test_a_bad_zones_entry_in_the_config_is_one_line(
    sdt_in_process, tmp_path, zones, message
) -> None:
    path = tmp_path / "sweep.toml"
    path.write_text(SWEEP.format(zone="zone_agreement = 0.9", extra=f"zones = {zones}\n"))
    lines = _refused(sdt_in_process, path, tmp_path / "o")
    assert f"{path}: [benchmark] zones: {message}" in lines[0]


def test_a_sweep_with_zone_agreement_writes_the_share_counted_from_features_parquet(
    tmp_path,
) -> None:
    """End to end: the written share equals the count over features.parquet by the table.

    The table named in the config (group 2 flexible, not Motor-2's default) is the one used.
    """
    path = tmp_path / "sweep.toml"
    chosen = "iso10816-3-group2-flexible"
    zones = f'zones = {{ "Motor-2" = "{chosen}" }}\n'
    cache = f'cache_dir = "{tmp_path / "cache"}"\n'
    path.write_text(SWEEP.format(zone="zone_agreement = 0.9", extra=zones + cache))
    out = tmp_path / "o"
    result = CliRunner().invoke(
        app, ["explore", str(path), "--out", str(out), "--strategy", "exhaustive"]
    )
    assert result.exit_code == 0, result.output
    cuts = builtin_tables()[chosen].cuts
    features = pd.read_parquet(out / "features.parquet")
    key = ["recording_id", "acquisition", "window"]
    reference = json.loads((out / "summary.json").read_text())["reference"]
    ref = features[features["sensor"] == reference].set_index(key)["V_RMS"]
    pareto = pd.read_csv(out / "pareto.csv").drop_duplicates("point").set_index("point")
    assert len(pareto) == 2
    for point, row in pareto.iterrows():
        mine = features[features["sensor"] == point].set_index(key)["V_RMS"]
        v_ref, v_pt = ref.loc[mine.index].to_numpy(), mine.to_numpy()
        zone_ref = sum(v_ref > c for c in cuts)  # boundaries below the value
        zone_pt = sum(v_pt > c for c in cuts)
        assert row["zone_agreement"] == pytest.approx(np.mean(zone_ref == zone_pt), abs=1e-12)
    spec = pd.read_csv(out / "min_spec.csv")
    assert {"min_level_macro_f1", "min_level_zones"} <= set(spec.columns)
    assert "zone agreement >= 0.9" in spec["target"].iloc[0]
    assert "Zone agreement per point" in result.output
