"""Benchmark: NLN-EMP CSV parsing (pyarrow reader + validation) vs pandas, and the cache.

Generates one file in the published format (header ``time,0,1,...``, 20 kHz,
240000 rows = 12 s per column) and times, in one run: our parser
(``parse_nln_csv``: multi-threaded pyarrow plus row/value/time checks), pandas'
default ``read_csv`` on the same file, and a cached re-read through the NLN-EMP
reader. Usage::

    .venv/bin/python benchmarks/bench_csv.py [--columns 20] [--rows 240000]
"""

from __future__ import annotations

import argparse
import tempfile
import timeit
from pathlib import Path

import numpy as np
import pandas as pd
from sdt_plugins.datasets.nln_emp import open_nln_emp
from sdt_plugins.datasets.nln_emp.csv_file import parse_nln_csv

from sdt_framework.data import write_nln_emp
from sdt_framework.data.recording import Dataset, Recording


def _best(func, repeat: int = 3) -> float:
    """Best wall time of ``repeat`` calls, s."""
    return min(timeit.repeat(func, number=1, repeat=repeat))


def main() -> None:
    """Write the file, time the three reads, print MB/s and speedups."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--columns", type=int, default=20)
    parser.add_argument("--rows", type=int, default=240000)
    args = parser.parse_args()
    data = np.random.default_rng(0).normal(0, 0.5, (args.columns, args.rows))
    with tempfile.TemporaryDirectory() as tmp:
        rec = Recording(
            "bench",
            "Motor-4",
            "70",
            "healthy",
            None,
            "healthy 1",
            "ch1",
            "b",
            20000.0,
            "g",
            args.columns,
            args.rows,
            (),
            "memory",
            lambda: data,
        )
        (path,) = write_nln_emp(Dataset("bench", [rec], []), tmp)
        size_mb = path.stat().st_size / 1e6
        ours = _best(lambda: parse_nln_csv(path))
        theirs = _best(lambda: pd.read_csv(path))
        cache = Path(tmp) / "cache"
        first = open_nln_emp(tmp, cache_dir=cache).recordings()[0]
        cold = _best(first.load, repeat=1)
        warm = _best(lambda: open_nln_emp(tmp, cache_dir=cache).recordings()[0].load())
    print(f"file: {args.columns} columns x {args.rows} rows, {size_mb:.1f} MB")
    print(f"sdt parse_nln_csv (pyarrow, validated): {ours:.3f} s  {size_mb / ours:7.1f} MB/s")
    print(f"pandas.read_csv (default):              {theirs:.3f} s  {size_mb / theirs:7.1f} MB/s")
    print(f"speedup vs pandas: {theirs / ours:.1f}x")
    print(f"reader first load (parse + cache write): {cold:.3f} s")
    print(f"reader cached re-load (open + load):     {warm:.3f} s  -> {cold / warm:.0f}x faster")


if __name__ == "__main__":
    main()
