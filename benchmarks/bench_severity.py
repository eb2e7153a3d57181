"""Zone grading and agreement: sdt's vectorised code beside a plain per-window loop.

A features table of N windows per sensor (reference + 2 MEMS, 2 machines, 5
channels), V_RMS log-uniform 0.3-20 mm/s. Times the pairing, grading and
same-zone share (`severity.agreement.paired_zones`) beside a plain Python loop
over windows doing the same, prints both and the ratio, then the whole
`zone_agreement` (alarms, confusion, recording intervals with 2000 resamples;
the resampling, `verdict.recordings.stratified_weights`, dominates it). Usage:

    .venv/bin/python benchmarks/bench_severity.py [--windows 20000]
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import pandas as pd

from sdt_framework.severity import assign_tables, zone_agreement
from sdt_framework.severity.agreement import paired_zones


def table(windows: int) -> pd.DataFrame:
    gen = np.random.default_rng(0)
    per = windows // 10
    frames = []
    for machine in ("Motor-2", "Motor-4"):
        for channel in ("ch1", "ch2", "ch3", "ch4", "ch5"):
            v = np.exp(gen.uniform(np.log(0.3), np.log(20.0), per))
            rec = np.arange(per) // 8
            base = pd.DataFrame(
                {
                    "machine": machine,
                    "channel": channel,
                    "recording_id": [f"{machine}/{channel}/{r}" for r in rec],
                    "condition": np.where(rec % 3 == 0, "healthy", "fault"),
                    "severity": pd.array(np.where(rec % 3 == 0, pd.NA, 1), dtype="Int64"),
                    "acquisition": 0,
                    "window": np.arange(per) % 8,
                }
            )
            for sensor, gain in (("ref", 1.0), ("a", 1.3), ("b", 0.9)):
                frames.append(base.assign(sensor=sensor, V_RMS=(gain * v).astype(np.float32)))
    return pd.concat(frames, ignore_index=True)


def plain(features: pd.DataFrame, cuts: dict[str, tuple[float, float, float]]) -> float:
    ref = {}
    for row in features[features["sensor"] == "ref"].itertuples():
        ref[(row.machine, row.channel, row.recording_id, row.window)] = row.V_RMS
    same = total = 0
    for row in features[features["sensor"] != "ref"].itertuples():
        c = cuts[row.machine]
        v_ref = ref[(row.machine, row.channel, row.recording_id, row.window)]
        z_s = sum(b < row.V_RMS for b in c)
        z_r = sum(v_ref > b for b in c)
        same += z_s == z_r
        total += 1
    return same / total


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--windows", type=int, default=20000)
    args = parser.parse_args()
    features = table(args.windows)
    assignments = assign_tables(["Motor-2", "Motor-4"])
    start = time.perf_counter()
    pairs = paired_zones(features, "ref", assignments)
    ours_share = float((pairs["zone_ref"] == pairs["zone_sensor"]).mean())
    ours = time.perf_counter() - start
    start = time.perf_counter()
    result = zone_agreement(features, "ref", assignments)
    full = time.perf_counter() - start
    cuts = {m: tuple(a.table.cuts) for m, a in assignments.items()}
    start = time.perf_counter()
    share = plain(features, cuts)
    loop = time.perf_counter() - start
    rows = result.zones[result.zones["channel"] == "all"]
    pooled = float((rows["share_same"] * rows["n_windows"]).sum() / rows["n_windows"].sum())
    assert abs(pooled - share) < 1e-12 and abs(ours_share - share) < 1e-12, (pooled, share)
    print(f"{len(features)} feature rows ({args.windows} windows per sensor)")
    print(f"pairing + grading + same-zone share, sdt (paired_zones): {ours:.3f} s")
    print(f"pairing + grading + same-zone share, plain loop:         {loop:.3f} s")
    print(f"ratio plain / sdt: {loop / ours:.1f}")
    print(f"zone_agreement, every figure and interval (2000 resamples): {full:.2f} s")


if __name__ == "__main__":
    main()
