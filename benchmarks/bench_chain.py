"""Throughput of the SDT chain against a plain per-acquisition implementation.

Degrades 60 s of 20 kHz signal as 50 acquisitions of 12 s (a 50 x 240000
batch) with each built-in profile, twice: through ``sdt_framework.chain.degrade``
(one batched call: fused mechanical+analog SOS cascade, rows filtered on all
CPUs, sampling by precomputed index arithmetic) and through the plain loop
below (per acquisition: ``sosfilt`` per filter, ``numpy.interp``, noise,
``sosfilt``, clip/round). Both draw the noise of acquisition i from
``seeding.rng(seed, i)``, so their outputs must be bit-identical; this is
asserted. Prints reference samples per second and the speed-up, with all
CPUs and with one thread (the algorithmic part: fused cascade, block-wise
execution, index-arithmetic sampling).

Then the extended chain: the ADXL345 profile with every built-in error stage
(cross-axis sensitivity on a triaxial node, offset and scale with a
temperature ramp, nonlinearity, Gauss-Markov, 1/f,
random walk, VRW, extra white noise, clock error with jitter) next to the paper
chain of the same profile, in the same run, with the throughput ratio.

Run: ``.venv/bin/python benchmarks/bench_chain.py [--repeats 3]``
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
from numpy.typing import NDArray
from scipy.signal import butter, sosfilt

from sdt_framework.chain import degrade
from sdt_framework.registry import build_registry
from sdt_framework.seeding import rng
from sdt_framework.specs import SensorSpec

FS = 20000.0
ACQUISITIONS, SAMPLES = 50, 240000
SEED = 0


def plain_degrade(x: NDArray[np.float64], fs: float, s: SensorSpec, seed: int) -> NDArray:
    """The chain written the obvious way: a Python loop over acquisitions."""
    s = s.at_rate(fs)
    target = s.sampling_rate_hz
    analog = [
        butter(order, fc, fs=fs, output="sos")
        for order, fc in ((s.mech_order, s.mech_cutoff_hz), (s.analog_order, s.analog_cutoff_hz))
        if fc is not None and fc < fs / 2
    ]
    digital = None
    if s.digital_cutoff_hz is not None and s.digital_cutoff_hz < target / 2:
        digital = butter(s.digital_order, s.digital_cutoff_hz, fs=target, output="sos")
    n = x.shape[1]
    m = int((n - 1) * target / fs) + 1
    t_in, t_out = np.arange(n) / fs, np.arange(m) / target
    sigma = s.noise_density_ug_rthz * 1e-6 * np.sqrt(target / 2)
    step = s.quantisation_step_g
    out = []
    for i, row in enumerate(x):
        y = row.copy()
        for sos in analog:
            y = sosfilt(sos, y)
        if target != fs:
            y = np.interp(t_out, t_in, y)
        if s.inject_noise:
            y = y + sigma * rng(seed, i).standard_normal(y.size)
        if digital is not None:
            y = sosfilt(digital, y)
        if s.requantise:
            y = step * np.round(np.clip(y, -s.full_scale_g, s.full_scale_g) / step)
        out.append(y)
    return np.vstack(out)


def best_time(fn, repeats: int) -> tuple[float, NDArray]:
    """Best wall time of ``repeats`` calls, and the last result."""
    best, result = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best, result


def main() -> None:
    """Time both implementations for every built-in profile and print a table."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    t = np.arange(SAMPLES) / FS
    gen = np.random.default_rng(1)
    x = np.sin(2 * np.pi * 24.6 * t) + 0.5 * gen.standard_normal((ACQUISITIONS, SAMPLES))
    total = x.size
    print(
        f"batch {ACQUISITIONS} x {SAMPLES} at {FS:g} Hz ({total / FS:g} s of signal), "
        f"{len(os.sched_getaffinity(0))} CPUs, best of {args.repeats}"
    )
    print(
        f"{'profile':<18}{'chain Msamp/s':>15}{'1 thread':>10}{'plain Msamp/s':>15}"
        f"{'speed-up':>10}{'1 thread':>10}"
    )
    for sensor in build_registry().sensors():
        ours_t, ours = best_time(lambda s=sensor: degrade(x, FS, s, SEED)[0], args.repeats)
        one_t, one = best_time(lambda s=sensor: degrade(x, FS, s, SEED, threads=1)[0], args.repeats)
        plain_t, plain = best_time(lambda s=sensor: plain_degrade(x, FS, s, SEED), args.repeats)
        np.testing.assert_array_equal(ours, plain)
        np.testing.assert_array_equal(one, plain)
        print(
            f"{sensor.name:<18}{total / ours_t / 1e6:>15.1f}{total / one_t / 1e6:>10.1f}"
            f"{total / plain_t / 1e6:>15.1f}{plain_t / ours_t:>9.2f}x{plain_t / one_t:>9.2f}x"
        )

    extended_rows(x, args.repeats)


EXTENDED = [
    {"name": "cross-axis", "params": {"pct": 1}},
    {
        "name": "offset",
        "params": {
            "offset_mg": 20,
            "tempco_mg_per_c": 0.4,
            "temperature": {"kind": "ramp", "rate_c_per_s": 0.5},
        },
    },
    {"name": "scale", "params": {"error_pct": 2, "tempco_pct_per_c": 0.01}},
    {"name": "nonlinearity", "params": {"second_pct_fs": 0.5, "third_pct_fs": 0.2}},
    {"name": "gauss-markov", "params": {"sigma_ug": 100, "tau_s": 1}},
    {"name": "flicker", "params": {"bias_instability_ug": 50}},
    {"name": "random-walk", "params": {"k_ug_rts": 5}},
    {"name": "vrw", "params": {"vrw_mps_rthr": 0.02}},
    {"name": "white-noise", "params": {"density_ug_rthz": 50}},
    {"name": "clock", "params": {"odr_error_pct": 0.5, "jitter_s": 1e-6}},
]


def extended_rows(x: NDArray[np.float64], repeats: int) -> None:
    """The paper chain of adxl345 and the same profile with every error stage."""
    registry = build_registry()
    paper = registry.sensor("adxl345")
    extended = registry.bind(
        SensorSpec.model_validate({**paper.model_dump(), "name": "adxl345-ext", "stages": EXTENDED})
    )
    node = {"y": np.roll(x, 1, axis=1), "z": -np.roll(x, 2, axis=1)}  # the other two axes
    print(f"\n{'chain':<18}{'Msamp/s':>15}{'1 thread':>10}")
    speeds = []
    for sensor in (paper, extended):
        all_t, _ = best_time(lambda s=sensor: degrade(x, FS, s, SEED, other_axes=node)[0], repeats)
        one_t, _ = best_time(
            lambda s=sensor: degrade(x, FS, s, SEED, threads=1, other_axes=node)[0], repeats
        )
        speeds.append(x.size / all_t)
        print(f"{sensor.name:<18}{x.size / all_t / 1e6:>15.1f}{x.size / one_t / 1e6:>10.1f}")
    print(f"extended / paper throughput: {speeds[1] / speeds[0]:.2f}")


if __name__ == "__main__":
    main()
