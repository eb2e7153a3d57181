"""How the default protocol scales: per-phase times, peak memory and wall time over ideal.

The default protocol (every default sensor, classifier, scenario; 10 repeats:
900 runs) on the synthetic pump with ``dataset_options.acquisitions`` 1 and 5
(20 with ``--full``), once with ``--jobs N`` (local loky processes) and once
on a local Dask cluster of W workers. Each run starts from an empty feature
cache and output folder, in a fresh process, and goes through what ``sdt
benchmark`` does: plan (and generate the data), featurise, classify, write the
output files, write the report.

Printed per run:

- the time of each phase, and of the serial tail (outputs + report);
- peak memory: the largest sum of resident memory over the process and its
  workers, sampled every 0.2 s;
- wall over ideal: the phase's wall time over the time the workers spent in
  its tasks (each recording's featurisation, each run's fit and predict,
  measured inside the worker), summed and divided by the workers. 1.0 is a
  perfect spread; ``compute`` covers features and classifiers, ``whole`` also
  the serial start and tail;
- whether the two engines' results are identical (every column but the fit
  times), which the order of submission must not change.

Usage:

    .venv/bin/python benchmarks/bench_scale.py                   # acquisitions 1 and 5
    .venv/bin/python benchmarks/bench_scale.py --acquisitions 1  # one size only
    .venv/bin/python benchmarks/bench_scale.py --full            # 1, 5 and 20 (hours)
    .venv/bin/python benchmarks/bench_scale.py --acquisitions 1 --repeats 2  # a loaded machine
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import pandas as pd
import psutil

TARGET = 1.15  # the "Done means": wall over ideal on acquisitions = 5


class PeakMemory:
    """Largest summed RSS of this process and its descendants, sampled in a thread."""

    def __init__(self, every: float = 0.2) -> None:
        self.every, self.peak, self._stop = every, 0, threading.Event()
        self._thread = threading.Thread(target=self._watch, daemon=True)

    def _watch(self) -> None:
        me = psutil.Process()
        while not self._stop.is_set():
            total = 0
            for proc in [me, *me.children(recursive=True)]:
                try:
                    total += proc.memory_info().rss
                except psutil.Error:
                    continue
            self.peak = max(self.peak, total)
            self._stop.wait(self.every)

    def __enter__(self) -> PeakMemory:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join()


def one(acquisitions: int, engine: str, workers: int, out: Path, cache: Path, repeats: int) -> dict:
    """Run the default protocol once in this process; return its measurements."""
    from sdt_framework.bench import load_config, run_benchmark_folder
    from sdt_framework.registry import build_registry
    from sdt_framework.report import write_report

    backend = {"backend": "dask"} if engine == "dask" else {}
    overrides = {
        "dataset_options": {"acquisitions": acquisitions},
        "jobs": workers,
        "cache_dir": str(cache),
        **backend,
        **({"repeats": repeats} if repeats else {}),
    }
    times: dict[str, float] = {}
    marks: dict[str, float] = {}

    def planned(plan) -> None:
        marks["plan"] = time.perf_counter()

    def progress(stage: str, done: int, total: int) -> None:  # the last call ends the runs
        marks["ran"] = time.perf_counter()

    def report(run) -> None:  # the outputs are written; the folder is still locked
        marks["outputs"] = time.perf_counter()
        write_report(out, registry=registry)
        marks["report"] = time.perf_counter()

    with PeakMemory() as memory:
        start = time.perf_counter()
        registry = build_registry()
        config = load_config(None, overrides)
        run = run_benchmark_folder(
            config, registry, out, yes=True, progress=progress, check=planned, finish=report
        )
        times["total"] = time.perf_counter() - start
    result, results = run.result, run.results
    times["plan"] = marks["plan"] - start
    times |= result.seconds
    # the serial tail: the pool's shutdown and the output files, then the report
    times["outputs"] = marks["outputs"] - marks["ran"]
    times["report"] = marks["report"] - marks["outputs"]
    results.drop(columns="fit_seconds").to_parquet(out / "compare.parquet")
    return {
        "times": times,
        "task_seconds": result.task_seconds,
        "peak_bytes": memory.peak,
        "runs": len(results),
    }


def measure(acquisitions: int, engine: str, workers: int, root: Path, repeats: int) -> dict:
    """:func:`one` in a fresh process (imports, pools and memory start from nothing)."""
    out = root / f"{engine}-{acquisitions}"
    cache = root / f"cache-{engine}-{acquisitions}"
    command = [sys.executable, __file__, "--one", engine, str(workers), str(acquisitions)]
    command += [str(out), str(cache), str(repeats)]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    data = json.loads((out / "bench_scale.json").read_text())
    data["results"] = out / "compare.parquet"
    return data


def line(label: str, acquisitions: int, workers: int, data: dict) -> tuple[str, float]:
    t, tasks = data["times"], data["task_seconds"]
    compute = t["features"] + t["classify"]
    ideal = (tasks["features"] + tasks["classify"]) / workers
    tail = t["outputs"] + t["report"]
    ratio = compute / ideal
    text = (
        f"acq {acquisitions:>2} {label:<13} {data['runs']} runs: plan {t['plan']:.0f} s, "
        f"features {t['features']:.0f} s, classify {t['classify']:.0f} s, outputs "
        f"{t['outputs']:.1f} s, report {t['report']:.1f} s (tail {tail:.0f} s), total "
        f"{t['total']:.0f} s; peak {data['peak_bytes'] / 1e9:.2f} GB; summed task time "
        f"{tasks['features'] + tasks['classify']:.0f} s; wall/ideal compute {ratio:.2f}, "
        f"whole {t['total'] / ideal:.2f}"
    )
    if acquisitions >= 5:
        text += f" (target {TARGET}: {'OK' if ratio <= TARGET else 'OVER'})"
    return text, ratio


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--acquisitions", type=int, nargs="*", help="sizes (default 1 5)")
    parser.add_argument("--full", action="store_true", help="also acquisitions = 20 (hours)")
    parser.add_argument("--jobs", type=int, default=2, help="local processes (default 2)")
    parser.add_argument("--dask-workers", type=int, default=4, help="Dask workers (default 4)")
    parser.add_argument("--keep", type=Path, help="write the results folders here (kept)")
    parser.add_argument("--only", choices=["local", "dask"], help="measure one engine only")
    parser.add_argument(
        "--repeats", type=int, default=0, help="repetitions (default: the protocol's 10)"
    )
    parser.add_argument("--one", nargs=6, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.one:
        engine, workers, acquisitions, out, cache, repeats = args.one
        data = one(int(acquisitions), engine, int(workers), Path(out), Path(cache), int(repeats))
        (Path(out) / "bench_scale.json").write_text(json.dumps(data))
        return
    sizes = args.acquisitions or ([1, 5, 20] if args.full else [1, 5])
    print(
        f"machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores, "
        f"python {platform.python_version()}; load average {os.getloadavg()[0]:.1f}; "
        f"repeats {args.repeats or 10}",
        flush=True,
    )
    engines = [("local", args.jobs, f"--jobs {args.jobs}"), ("dask", args.dask_workers, "")]
    engines = [e for e in engines if args.only in (None, e[0])]
    with tempfile.TemporaryDirectory() as tmp:
        root = args.keep or Path(tmp)
        for acquisitions in sizes:
            measured = []
            for engine, workers, label in engines:
                label = label or f"dask x{workers}"
                data = measure(acquisitions, engine, workers, root, args.repeats)
                print(line(label, acquisitions, workers, data)[0], flush=True)
                measured.append(pd.read_parquet(data["results"]))
            if len(measured) < 2:
                continue
            same = measured[0].equals(measured[1])
            print(
                f"acq {acquisitions:>2} identical results (--jobs {args.jobs} vs dask "
                f"x{args.dask_workers}, every column but fit_seconds): {'yes' if same else 'NO'}",
                flush=True,
            )


if __name__ == "__main__":
    main()
