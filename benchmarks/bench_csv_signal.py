"""Benchmark: the shared CSV signal reader vs plain pyarrow and numpy, tall and wide files.

``read_csv_signal`` (header and time-column detection, every value checked
finite) parses files of up to 256 columns with pyarrow and wider ones with
``numpy.loadtxt``. This times, in one run, on a tall file (``time`` + 20
acquisition columns x 240 000 rows, the NLN-EMP shape) and a wide one
(``numpy.savetxt`` of 2 x 240 000): our reader, plain ``pyarrow.csv.read_csv``
and plain ``numpy.loadtxt``, and prints the ratios. Usage::

    .venv/bin/python benchmarks/bench_csv_signal.py [--rows 240000]
"""

from __future__ import annotations

import argparse
import tempfile
import timeit
from pathlib import Path

import numpy as np
import pyarrow.csv as pacsv

from sdt_framework.signals.csv_rule import read_csv_signal


def _best(func, repeat: int = 3) -> float:
    """Best wall time of ``repeat`` calls, s."""
    return min(timeit.repeat(func, number=1, repeat=repeat))


def _row(name: str, path: Path) -> None:
    size = path.stat().st_size / 1e6
    ours = _best(lambda: read_csv_signal(path))
    options = pacsv.ReadOptions(autogenerate_column_names=name == "wide", block_size=1 << 26)
    arrow = _best(lambda: pacsv.read_csv(path, read_options=options))
    loadtxt = _best(lambda: np.loadtxt(path, delimiter=",", skiprows=1 if name == "tall" else 0))
    print(
        f"{name:5s} {size:6.1f} MB  ours {ours:6.3f} s  pyarrow {arrow:6.3f} s "
        f"({arrow / ours:5.2f}x)  numpy.loadtxt {loadtxt:6.3f} s ({loadtxt / ours:5.2f}x)"
    )


def main() -> None:
    """Write both files, time the three readers on each, print seconds and ratios."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=240000)
    args = parser.parse_args()
    rng = np.random.default_rng(0)
    with tempfile.TemporaryDirectory() as tmp:
        tall = Path(tmp) / "tall.csv"
        data = np.column_stack([np.arange(args.rows) / 20000, rng.normal(0, 0.5, (args.rows, 20))])
        header = ",".join(["time", *map(str, range(20))])
        np.savetxt(tall, data, delimiter=",", fmt="%.6g", header=header, comments="")
        wide = Path(tmp) / "wide.csv"
        np.savetxt(wide, rng.normal(0, 0.5, (2, args.rows)), delimiter=",", fmt="%.17g")
        print("ratio = other reader's time / ours (> 1: ours faster); ours also checks every value")
        _row("tall", tall)
        _row("wide", wide)


if __name__ == "__main__":
    main()
