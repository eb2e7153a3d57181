"""Design-space exploration speed: shared chain prefix vs independent profiles, and points/hour.

1. Featurisation of a 16-point sweep over target-rate parameters (sampling
   rate x noise density, the ``examples/sweeps/rate_noise.toml`` grid) on the
   synthetic default's recordings: with the recording-rate stages shared
   (``chain.shared.SharedPrefix``: mechanical + analog filters once per
   recording) against the same 16 points degraded independently
   (``chain.degrade`` per point). Features are checked bit-identical.
2. The full default protocol's points per hour: ``sdt explore`` on a 4-point
   sweep (plus reference and base) with the default protocol, empty cache.

Usage:

    .venv/bin/python benchmarks/bench_explore.py            # both
    .venv/bin/python benchmarks/bench_explore.py --sharing  # part 1 only
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from sdt_framework.chain import degrade
from sdt_framework.chain.shared import SharedPrefix
from sdt_framework.data.synth_dataset import open_synthetic
from sdt_framework.explore import build_points, design_points, load_sweep
from sdt_framework.features import extract
from sdt_framework.registry import build_registry

ROOT = Path(__file__).resolve().parents[1]
SWEEP = ROOT / "examples" / "sweeps" / "rate_noise.toml"


def sharing(recordings: int, duration: float) -> None:
    registry = build_registry()
    sweep, _ = load_sweep(SWEEP)
    base = registry.sensor(sweep.base)
    points, _ = build_points(sweep, base, design_points(sweep))
    specs = [p.spec for p in points]
    paper8 = registry.feature_set("paper8")
    dataset = open_synthetic(duration=duration)
    chosen = dataset.recordings()[:recordings]
    loaded = [(r, r.load()) for r in chosen]
    samples = sum(x.size for _, x in loaded)

    def featurise(y, fs):
        return extract(y, fs, paper8).values

    start = time.perf_counter()
    plain = [
        featurise(*degrade(x, r.sampling_rate_hz, s, seed=1, threads=1))
        for r, x in loaded
        for s in specs
    ]
    plain_s = time.perf_counter() - start
    start = time.perf_counter()
    shared = []
    for r, x in loaded:
        prefix = SharedPrefix(x, r.sampling_rate_hz, threads=1)
        shared += [featurise(*prefix.degrade(s, seed=1)) for s in specs]
    shared_s = time.perf_counter() - start
    same = all(np.array_equal(a, b) for a, b in zip(plain, shared, strict=True))
    print(
        f"16-point sweep, {len(loaded)} recordings ({samples / 1e6:.1f} M samples at 20 kHz): "
        f"independent {plain_s:.2f} s, shared prefix {shared_s:.2f} s -> "
        f"{plain_s / shared_s:.2f}x (target >= 3x); features bit-identical: {same}",
        flush=True,
    )


def points_per_hour() -> None:
    text = SWEEP.read_text().replace(
        "sampling_rate_hz = { levels = [800, 1600, 3200, 6400] }",
        "sampling_rate_hz = { levels = [1600, 3200] }",
    )
    text = text.replace(
        "noise_density_ug_rthz = { levels = [25, 90, 290, 1000] }",
        "noise_density_ug_rthz = { levels = [90, 290] }",
    )
    text = text[: text.index("[benchmark]")]  # the full default protocol
    with tempfile.TemporaryDirectory() as tmp:
        sweep = Path(tmp) / "sweep.toml"
        sweep.write_text(text)
        command = [sys.executable, "-m", "sdt_framework", "explore", str(sweep)]
        command += ["--out", str(Path(tmp) / "out"), "--no-report", "--yes"]
        env = {**os.environ, "SDT_CACHE_DIR": str(Path(tmp) / "cache")}
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, env=env)
        seconds = time.perf_counter() - start
    print(
        f"full default protocol, 4 points + reference + base, empty cache: {seconds:.0f} s "
        f"-> {4 * 3600 / seconds:.0f} points per hour (6 sensors evaluated)",
        flush=True,
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sharing", action="store_true", help="measure only the sharing")
    parser.add_argument("--recordings", type=int, default=10, help="recordings to featurise")
    parser.add_argument("--duration", type=float, default=12.0, help="seconds per acquisition")
    args = parser.parse_args()
    print(
        f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}",
        flush=True,
    )
    sharing(args.recordings, args.duration)
    if not args.sharing:
        points_per_hour()


if __name__ == "__main__":
    main()
