"""What the caches' content digest of data files costs (`sdt_framework.data.digest`).

Writes the synthetic pump as an NLN-EMP tree (255 CSV files, 1 s each, about
87 MB, as ``sdt dataset synth --duration 1``), reads it once (the page cache
warm, as after the run that wrote or read it), then times hashing every file,
a first run that also remembers each digest in a memo folder, and a later run
that finds them there. Usage:

    .venv/bin/python benchmarks/bench_digest.py
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.data import write_nln_emp
from sdt_framework.data.digest import SETTLE_NS, file_digest


def _timed(files: list[Path], memo: Path | None) -> float:
    start = time.perf_counter()
    for path in files:
        file_digest(path, memo)
    return time.perf_counter() - start


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp) / "pump"
        write_nln_emp(open_synthetic(duration=1.0), root)
        files = sorted(p for p in root.rglob("*.csv"))
        size = sum(p.stat().st_size for p in files)
        for path in files:
            path.read_bytes()
        hashing = _timed(files, None)
        time.sleep(SETTLE_NS / 1e9 + 0.1)  # past the settling time: digests are remembered
        memo = Path(tmp) / "cache"
        first = _timed(files, memo)
        later = _timed(files, memo)
    print(
        f"{len(files)} files, {size / 1e6:.1f} MB: hashing every file {hashing:.2f} s "
        f"({size / 1e6 / hashing:.0f} MB/s); first run with the memo {first:.2f} s; "
        f"later runs {later:.2f} s ({later / len(files) * 1e3:.2f} ms per file)"
    )


if __name__ == "__main__":
    main()
