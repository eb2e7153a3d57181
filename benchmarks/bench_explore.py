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
from sdt_plugins.datasets.synthetic_pump.dataset import open_synthetic

from sdt_framework.bench.featurise import FeatureJob, featurise_recording, noise_seed
from sdt_framework.chain import degrade
from sdt_framework.explore import build_points, design_points, load_sweep
from sdt_framework.features import extract
from sdt_framework.registry import build_registry

ROOT = Path(__file__).resolve().parents[1]
SWEEP = ROOT / "examples" / "sweeps" / "rate_noise.toml"


def sharing(recordings: int, duration: float, repeats: int) -> None:
    registry = build_registry()
    sweep, _ = load_sweep(SWEEP)
    base = registry.sensor(sweep.base)
    points, _ = build_points(sweep, base, design_points(sweep))
    specs = tuple(p.spec for p in points)
    paper8 = registry.feature_set("paper8")
    chosen = open_synthetic(duration=duration).recordings()[:recordings]
    loaded = [(r, r.load()) for r in chosen]  # generated once, outside both timings
    samples = sum(x.size for _, x in loaded)

    start = time.perf_counter()  # plain: every point and repetition degraded on its own
    plain = [
        extract(
            *degrade(x, r.sampling_rate_hz, s, seed=noise_seed(s, 0, k, r.recording_id), threads=1),
            paper8,
        ).values
        for r, x in loaded
        for s in specs
        for k in range(repeats)
    ]
    plain_s = time.perf_counter() - start

    class Loaded:  # the recording with its samples already in memory
        def __init__(self, recording, data):
            self.recording, self.data = recording, data

        def __getattr__(self, name):
            return getattr(self.recording, name)

        def load(self):
            return self.data

    start = time.perf_counter()  # ours: bench.featurise, the benchmark's own code path
    ours = []
    for r, x in loaded:
        job = FeatureJob(Loaded(r, x), "bench", specs, paper8, repeats, 0, 0.64, 0.1, None)
        blocks = {(b.sensor, b.repeat): b.values for b in featurise_recording(job).blocks}
        ours += [blocks[(s.name, k)] for s in specs for k in range(repeats)]
    ours_s = time.perf_counter() - start
    same = all(np.array_equal(a, b) for a, b in zip(plain, ours, strict=True))
    print(
        f"16-point sweep x {repeats} repetitions, {len(loaded)} recordings "
        f"({samples / 1e6:.1f} M samples at 20 kHz): independent profiles {plain_s:.2f} s, "
        f"shared prefix (bench.featurise) {ours_s:.2f} s -> {plain_s / ours_s:.2f}x "
        f"(target >= 3x); features bit-identical: {same}",
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
        command += ["--strategy", "exhaustive"]  # every point through the full protocol
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
    parser.add_argument("--repeats", type=int, default=2, help="repetitions (quick preset: 2)")
    args = parser.parse_args()
    print(
        f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}",
        flush=True,
    )
    sharing(args.recordings, args.duration, args.repeats)
    if not args.sharing:
        points_per_hour()


if __name__ == "__main__":
    main()
