"""`sdt twin check` on the 25 s DAQ12006 pair, on one core, against a plain filter bank.

Times, pinned to one CPU with one BLAS/FFT thread: reading the pair (idelib,
both channels, the uneven one resampled), the whole check (alignment with the
twin, Welch spectra of reference, twin and device, bands, transfer, floors),
and beside it the plain way to get the same band table: a bank of
4th-order Butterworth band-pass filters (one per third octave, each run over
every axis of the device and of the twin, RMS of the output). Both band
tables are printed side by side on the judgeable bands so the ratio compares
like with like (the filter bank's skirts let a neighbour's tone leak in, so
weak bands beside a strong tone differ; the strong ones agree).

Run: ``.venv/bin/python benchmarks/bench_twin_check.py [--repeats 3]``
"""

from __future__ import annotations

import os

os.environ.setdefault("OMP_NUM_THREADS", "1")
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("MKL_NUM_THREADS", "1")

import argparse
import time
from pathlib import Path

import numpy as np
from scipy import signal

from sdt_framework.registry import build_registry
from sdt_framework.twin import check_twin, load_pair
from sdt_framework.twin.align import align
from sdt_framework.twin.spectra import third_octaves

PAIR = Path(__file__).parents[1] / "tests" / "data" / "endaq" / "DAQ12006_000005.IDE"


def filter_bank_rms(x: np.ndarray, fs: float, bands: np.ndarray) -> np.ndarray:
    """Band RMS per row and band, the plain way: a band-pass filter per band, RMS of its output."""
    out = np.empty((x.shape[0], len(bands)))
    for b, (lo, _, hi) in enumerate(bands):
        sos = signal.butter(4, [lo, min(hi, 0.999 * fs / 2)], btype="bandpass", fs=fs,
                            output="sos")  # fmt: skip
        y = signal.sosfiltfilt(sos, x, axis=-1)
        out[:, b] = np.sqrt(np.mean(y**2, axis=-1))
    return out


def best(fn, repeats: int):
    """Best wall time of ``repeats`` calls, and the last result."""
    fastest, result = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        result = fn()
        fastest = min(fastest, time.perf_counter() - start)
    return fastest, result


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
    registry = build_registry()
    sensor, readers = registry.sensor("adxl357"), registry.signal_readers()
    t_load, pair = best(lambda: load_pair(PAIR, "adxl357", readers=readers), args.repeats)
    t_check, result = best(lambda: check_twin(pair, sensor), args.repeats)
    a = align(pair, sensor)
    bands = third_octaves(10.0, a.rate_hz / 2)
    t_plain, plain = best(
        lambda: (filter_bank_rms(a.device, a.rate_hz, bands),
                 filter_bank_rms(a.twin, a.rate_hz, bands)),
        args.repeats,
    )  # fmt: skip
    t_align, _ = best(lambda: align(pair, sensor), args.repeats)
    axes = {axis: i for i, axis in enumerate(pair.device.axes)}
    centres = [round(float(c), 3) for c in bands[:, 1]]
    print(f"{PAIR.name}: {pair.device.values.shape[1]} device samples x {len(axes)} axes, "
          f"{len(bands)} third-octave bands, one core")  # fmt: skip
    print(f"{'band':>9} {'axis':>4} {'real (ours)':>12} {'real (bank)':>12} "
          f"{'twin (ours)':>12} {'twin (bank)':>12}")  # fmt: skip
    for row in (b for b in result.bands if b.judgeable):
        i, k = axes[row.axis], centres.index(round(row.f_centre_hz, 3))
        ours = f"{row.real_rms_g:>12.4g} {plain[0][i, k]:>12.4g}"
        bank = f"{row.twin_rms_g:>12.4g} {plain[1][i, k]:>12.4g}"
        print(f"{row.f_centre_hz:>7.0f}Hz {row.axis:>4} {ours} {bank}")
    bands_ours = t_check - t_align
    print(f"read the pair (idelib, 2 channels): {t_load:.2f} s")
    print(
        f"sdt twin check (all of it): {t_check:.2f} s, of which alignment and twin "
        f"{t_align:.2f} s; read + check {t_load + t_check:.2f} s (target: under 5 s)"
    )
    print(
        f"band table: ours (Welch spectra, bands, transfer, floors) {bands_ours:.3f} s vs "
        f"plain filter bank (bands only) {t_plain:.3f} s: {t_plain / bands_ours:.1f}x"
    )


if __name__ == "__main__":
    main()
