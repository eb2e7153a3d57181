"""Wall-clock time of `sdt benchmark --quick` and of the full default protocol.

Each run starts from an empty feature cache and an empty output folder, so the
figures include synthetic data generation, the SDT chain, feature extraction
and every classifier fit. Usage:

    .venv/bin/python benchmarks/bench_benchmark.py            # quick and full
    .venv/bin/python benchmarks/bench_benchmark.py --quick    # quick only
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

LIMITS = {"quick": 120.0, "full": 900.0}  # seconds, from the "Done means"


def run(name: str, extra: list[str]) -> float:
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out"
        command = [
            sys.executable,
            "-m",
            "sdt_framework",
            "benchmark",
            *extra,
            "--out",
            str(out),
            "--cache-dir",
            str(Path(tmp) / "cache"),
            "--no-report",
        ]
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
        seconds = time.perf_counter() - start
        summary = json.loads((out / "summary.json").read_text())
    print(
        f"{name:>5}: {seconds:7.1f} s wall ({summary['runs']} runs, "
        f"{summary['recordings']} recordings; features {summary['seconds']['features']:.0f} s, "
        f"classifiers {summary['seconds']['classify']:.0f} s) limit {LIMITS[name]:.0f} s -> "
        f"{'OK' if seconds < LIMITS[name] else 'OVER'}",
        flush=True,
    )
    return seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="measure only the quick preset")
    args = parser.parse_args()
    print(
        f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"python {platform.python_version()}"
    )
    run("quick", ["--quick"])
    if not args.quick:
        run("full", [])


if __name__ == "__main__":
    main()
