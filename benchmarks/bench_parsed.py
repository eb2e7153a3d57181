"""A campaign of LVM files scanned, then read: whole-file parses kept by memory, against
parsing at every call.

A manifest scans every file, then a benchmark probes every file before it reads
the first; LVM is text, so a scan, a probe and a read each need the whole file
parsed. sdt keeps the parses (:func:`sdt_framework.signals.parsed.keep_parsed`, up
to 256 MB of arrays); the plain way is lvm_read's ``read`` at every call, what a
cache of the last file or two amounted to here. The file is a real LabVIEW
recording (ARTS Lab dataset 5, CC BY-SA 4.0, in ``tests/data/readers/corpus``),
copied to make a campaign; both ways give the same samples (checked). Usage:

    .venv/bin/python benchmarks/bench_parsed.py [--files 8]
"""

from __future__ import annotations

import argparse
import shutil
import tempfile
import time
from pathlib import Path

import lvm_read
import numpy as np

from sdt_framework.registry import build_registry
from sdt_framework.signals.files import read_signal, scan_file

REAL = Path(__file__).parents[1] / "tests/data/readers/corpus/arts-lab-dataset5-Test_001.lvm"
CHANNEL = "Acceleration_0"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--files", type=int, default=8, help="files in the campaign")
    args = parser.parse_args()
    readers = build_registry().signal_readers()
    with tempfile.TemporaryDirectory() as folder:
        files = [Path(folder) / f"run{k}.lvm" for k in range(args.files)]
        for file in files:
            shutil.copyfile(REAL, file)
        start = time.perf_counter()
        for file in files:
            scan_file(file, readers)
        ours = [read_signal(file, readers, CHANNEL) for file in files]
        kept = time.perf_counter() - start
        start = time.perf_counter()
        for file in files:  # the scan pass: one parse a file
            lvm_read.read(str(file), read_from_pickle=False, dump_file=False)
        plain = [
            lvm_read.read(str(file), read_from_pickle=False, dump_file=False)[0]["data"][:, 1]
            for file in files
        ]
        each = time.perf_counter() - start
    for got, want in zip(ours, plain, strict=True):
        np.testing.assert_array_equal(got[0], want)
    size = REAL.stat().st_size / 1e6
    print(f"{args.files} files of {size:.1f} MB, scanned then read ({CHANNEL}), same samples")
    print(f"parses kept: {kept:.2f} s; lvm_read at every call: {each:.2f} s ({each / kept:.1f}x)")


if __name__ == "__main__":
    main()
