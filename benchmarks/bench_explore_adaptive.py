"""Adaptive against exhaustive exploration: the same minimum specification, in how much time.

Runs ``sdt explore examples/sweeps/rate_noise.toml`` twice on the same data,
each with its own empty feature cache and without the report (the same for
both): ``--strategy exhaustive`` (every point through the full protocol) and
``--strategy adaptive`` (a screen of every point, then the full protocol on
the levels its bisection needs). Prints the estimates the command printed
before it started, both minimum-specification tables (best classifier), whether
the two ``min_spec.csv`` agree on every cell (every classifier), both wall
times and their ratio.

``--acquisitions N`` runs the sweep on ``dataset_options = { acquisitions = N }``
(the synthetic default holds one 12 s acquisition per run and channel; the
real archive 10-60); ``--estimate-only`` prints the product's estimates of
both strategies there without running either; ``--only adaptive`` runs the
adaptive strategy alone (its answer and wall time beside both estimates: the
real-size question, where the exhaustive run takes hours).

Usage:

    .venv/bin/python benchmarks/bench_explore_adaptive.py
    .venv/bin/python benchmarks/bench_explore_adaptive.py --acquisitions 5 --estimate-only
    .venv/bin/python benchmarks/bench_explore_adaptive.py --acquisitions 5 --only adaptive
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import pandas as pd
import tomli_w

ROOT = Path(__file__).resolve().parents[1]
SWEEP = ROOT / "examples" / "sweeps" / "rate_noise.toml"
KEYS = ["machine", "scenario", "classifier", "parameter"]


def sweep_file(folder: Path, acquisitions: int | None, jobs: int) -> Path:
    """The example sweep, with the data size and the processes asked for."""
    data = tomllib.loads(SWEEP.read_text())
    data["benchmark"]["jobs"] = jobs
    if acquisitions is not None:
        data["benchmark"]["dataset_options"] = {"acquisitions": acquisitions}
    path = folder / "rate_noise.toml"
    path.write_text(tomli_w.dumps(data))
    return path


def estimate_lines(path: Path) -> list[str]:
    """The two estimate lines ``sdt explore`` prints before it starts (the same functions)."""
    from sdt_framework.bench.estimate import estimate
    from sdt_framework.explore import load_sweep
    from sdt_framework.explore.adaptive import estimates
    from sdt_framework.explore.run import plan_explore
    from sdt_framework.explore.size import run_estimate
    from sdt_framework.registry import build_registry

    sweep, protocol = load_sweep(path)
    registry = build_registry()
    explore = plan_explore(sweep, protocol, {}, registry)
    exhaustive = run_estimate(explore.plan, estimate(explore.plan), report=False)
    return estimates(explore, registry, exhaustive, report=False)[0]


def run(path: Path, strategy: str, folder: Path) -> float:
    """One ``sdt explore`` run with an empty feature cache; its wall time."""
    out = folder / strategy
    command = [sys.executable, "-m", "sdt_framework", "explore", str(path)]
    command += ["--strategy", strategy, "--out", str(out), "--no-report", "--yes"]
    env = {**os.environ, "SDT_CACHE_DIR": str(folder / f"cache-{strategy}")}
    start = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True, env=env, check=False)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"sdt explore --strategy {strategy} failed:\n{done.stderr}")
    return seconds


def best_table(path: Path) -> pd.DataFrame:
    """The printed minimum-specification table: best classifier, machine x scenario."""
    table = pd.read_csv(path)
    best = table[table["classifier"] == "best"]
    return best.pivot_table(
        index=["machine", "scenario"], columns="parameter", values="min_level", dropna=False
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--acquisitions", type=int, default=None, help="acquisitions per run")
    parser.add_argument("--jobs", type=int, default=2, help="processes (default 2)")
    parser.add_argument("--estimate-only", action="store_true", help="print estimates only")
    parser.add_argument("--only", choices=["adaptive"], help="run the adaptive strategy alone")
    args = parser.parse_args()
    print(
        f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"Python {platform.python_version()}; data: "
        f"{'default' if args.acquisitions is None else f'acquisitions = {args.acquisitions}'}, "
        f"--jobs {args.jobs}",
        flush=True,
    )
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        path = sweep_file(folder, args.acquisitions, args.jobs)
        print("\n".join(estimate_lines(path)), flush=True)
        if args.estimate_only:
            print("not run (--estimate-only): the estimates above are the product's own")
            return
        strategies = ("adaptive",) if args.only else ("adaptive", "exhaustive")
        timed = {strategy: run(path, strategy, folder) for strategy in strategies}
        tables = {s: pd.read_csv(folder / s / "min_spec.csv") for s in timed}
        for strategy in timed:
            print(f"\n{strategy} minimum specification (best classifier):")
            print(best_table(folder / strategy / "min_spec.csv").to_string())
        if args.only:
            refined = pd.read_csv(folder / "adaptive" / "refinement.csv")
            print(
                f"\nadaptive: {refined['point'].nunique()} of 16 points at full fidelity in "
                f"{refined['round'].max()} rounds; wall time {timed['adaptive']:.0f} s"
            )
            return
        ours = tables["adaptive"].set_index(KEYS).sort_index()
        theirs = tables["exhaustive"].set_index(KEYS).sort_index()
        same = ours.index.equals(theirs.index) and ours["min_level"].equals(theirs["min_level"])
        refined = pd.read_csv(folder / "adaptive" / "refinement.csv")
        print(
            f"\nmin_spec.csv equal on all {len(theirs)} cells (every classifier): {same}; "
            f"adaptive ran {refined['point'].nunique()} of 16 points at full fidelity in "
            f"{refined['round'].max()} rounds"
        )
        a, e = timed["adaptive"], timed["exhaustive"]
        print(f"wall time: adaptive {a:.0f} s, exhaustive {e:.0f} s -> ratio {e / a:.2f}x")


if __name__ == "__main__":
    main()
