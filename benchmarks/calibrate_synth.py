"""Calibration of the synthetic pump against published statistics of the real NLN-EMP data.

For every calibrated figure this prints the published value, the synthetic value
(seed 0, and the median over ``--seeds`` seeds: a published value is itself one
realisation of a run-to-run scatter, and ratios of log-normally scattered runs
are skewed, so the median is the typical value), their ratio (median /
published), the 10-90 % range over the seeds, whether the median is within a
factor 1.5 (or inside the stated bound) and the source. The synthetic value is
measured the way the source measured the real archive:

- source A: band RMS per 12 s acquisition, ``scipy.signal.welch`` with
  4096-sample Hann segments, PSD integrated over the band by trapezoids
  (its code/utils.py ``band_rms``); a run's value is the mean over its acquisitions;
- source B: overall RMS of ch1 per acquisition (its column ``vibration`` is the
  RMS in g times 9810 / (2 pi 50) mm/s per g; divided back for the table);
- the paper's clipping statements: the product's own SDT chain, noise off.

It also times the generation of the whole default dataset (every recording).
The published values are summaries of the sources' per-acquisition tables (run
means over 15-60 acquisitions); docs/data.md gives each one's exact location.

Run: ``.venv/bin/python benchmarks/calibrate_synth.py [--seeds 8] [--markdown]``
"""

from __future__ import annotations

import argparse
import time
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
from scipy import signal
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sdt_plugins.datasets.synthetic_pump.generate import FS_HZ, generate_run

from sdt_framework.chain import degrade
from sdt_framework.registry import build_registry

#: the published figures, their sources and checks (targets/published_figures.toml: each
#: figure's source, and how it follows from the source's run means where it gives them)
TARGETS = tomllib.loads(
    (Path(__file__).parent / "targets" / "published_figures.toml").read_text(encoding="utf-8")
)
SOURCES: dict[str, str] = TARGETS["sources"]


def _levels(name: str, *levels: int) -> list[str]:
    return [f"{name} {k}" for k in levels]


MACHINES = {"M4": "Motor-4", "M2": "Motor-2"}
RUNS = {
    "H": _levels("healthy", 1, 2, 3),
    "H1": ["healthy 1"],
    "UM1": ["unbalance motor 1"],
    "UM6": ["unbalance motor 6"],
    "UM14": _levels("unbalance motor", 1, 2, 3, 4),
    "UP1": ["unbalance pump 1"],
    "UP3": ["unbalance pump 3"],
    "AP1": ["align parallel 1"],
    "AP4": ["align parallel 4"],
    "AA5": ["align angular 5"],
    "BI1": ["bearing bpfi 1"],
    "BI3": ["bearing bpfi 3"],
    "BO1": ["bearing bpfo 1"],
    "BO3": ["bearing bpfo 3"],
    "IMP": _levels("impeller", 1, 2, 3),
    "BP": _levels("bearing pump", 1, 2, 3),
}
CHANNELS = {"Motor-4": ("ch1", "ch2", "ch5"), "Motor-2": ("ch1",)}


def band_rms(x: np.ndarray, lo: float, hi: float) -> float:
    """RMS in [lo, hi) Hz: Welch PSD (4096-sample Hann segments) integrated by trapezoids."""
    f, p = signal.welch(x - x.mean(), fs=FS_HZ, nperseg=4096)
    sel = (f >= lo) & (f < hi)
    return float(np.sqrt(np.trapezoid(p[sel], f[sel])))


def measure(x: np.ndarray, band: str) -> float:
    """Overall RMS (``all``) or band RMS (``10-200``, ``1k-9k``) of one acquisition."""
    if band == "all":
        return float(np.sqrt(np.mean(x * x)))
    lo, hi = (float(v.replace("k", "e3")) for v in band.split("-"))
    return band_rms(x, lo, hi)


def cv(values: np.ndarray) -> float:
    return float(np.std(values, ddof=1) / np.mean(values))


@cache
def run(machine: str, name: str, seed: int, duration: float, acquisitions: int = 1) -> dict:
    condition, level = name.rsplit(" ", 1)
    return generate_run(
        machine,
        condition,
        int(level),
        channels=CHANNELS[machine],
        acquisitions=acquisitions,
        duration_s=duration,
        seed=seed,
    )


def evaluate(spec: str, seed: int, duration: float) -> float:
    """The synthetic value of one figure's measure for one seed."""
    what, mach, runs, ch, band = spec.split()
    machine = MACHINES[mach]

    def values(token: str) -> np.ndarray:
        return np.array(
            [
                np.mean([measure(x, band) for x in run(machine, r, seed, duration)[ch]])
                for r in RUNS[token]
            ]
        )

    if what == "mean":
        return float(values(runs).mean())
    if what == "cv":
        return cv(values(runs))
    if what == "ratio":
        a, b = runs.split("/")
        return float(values(a).mean() / values(b).mean())
    if what == "acv":  # five acquisitions of one run
        return cv(
            np.array([measure(x, band) for x in run(machine, RUNS[runs][0], seed, duration, 5)[ch]])
        )
    if what == "share":
        x = run(machine, RUNS[runs][0], seed, duration)[ch][0]
        return measure(x, band) / measure(x, "all")
    if what == "peak":  # the reference sensor's range (g) in place of the band
        x = run(machine, "cavitation suction 4", seed, duration)[ch]
        return float(np.abs(x).max() / float(band))
    if what == "sdt":  # runs = sensor, band = its full scale (g)
        x = run(machine, "cavitation suction 4", seed, duration)[ch]
        y, _ = degrade(x, FS_HZ, build_registry().sensor(runs), noise=False)
        return float(np.abs(y).max() / float(band))
    raise ValueError(f"unknown measure {spec!r}")


def figures() -> list[tuple[str, ...]]:
    """(figure, published, source, check, measure) of every target, in the file's order."""
    return [
        (f["name"], str(f["published"]), f["source"], f["check"], f["measure"])
        for f in TARGETS["figure"]
    ]


def check(kind: str, published: float, value: float) -> str:
    ok = {"<=": value <= published, ">=": value >= published}.get(
        kind, 1 / 1.5 <= value / published <= 1.5
    )
    return "ok" if ok else "OUT"


def time_default_dataset() -> tuple[int, float, float]:
    """(recordings, wall s, CPU s) to generate every recording of the default dataset."""
    wall, cpu = time.perf_counter(), time.process_time()
    recordings = open_synthetic().recordings()
    for rec in recordings:
        rec.load()
    return len(recordings), time.perf_counter() - wall, time.process_time() - cpu


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=8, help="seeds for the median (default 8)")
    parser.add_argument("--duration", type=float, default=12.0, help="s per acquisition")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    parser.add_argument("--no-timing", action="store_true", help="skip the dataset timing")
    args = parser.parse_args()
    head = ("figure", "published", "seed 0", f"median of {args.seeds}", "10-90 %", "ratio", "check")
    rows = []
    for what, pub, src, kind, spec in figures():
        published = float(pub)
        vals = [evaluate(spec, seed, args.duration) for seed in range(args.seeds)]
        mid, low, high = np.median(vals), np.quantile(vals, 0.1), np.quantile(vals, 0.9)
        shown = pub if kind == "value" else f"{kind} {pub}"
        rows.append(
            (f"{what} [{src}]", shown, f"{vals[0]:.3g}", f"{mid:.3g}", f"{low:.3g}-{high:.3g}",
             f"{mid / published:.2f}", check(kind, published, mid))
        )  # fmt: skip
    if args.markdown:
        print("| " + " | ".join(head) + " |\n|" + "---|" * len(head))
        print("\n".join("| " + " | ".join(row) + " |" for row in rows))
    else:
        widths = [max(len(r[i]) for r in [head, *rows]) for i in range(len(head))]
        for row in [head, *rows]:
            print("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
    inside = sum(r[6] == "ok" for r in rows)
    print(f"{inside}/{len(rows)} figures within a factor 1.5 of the published value (or its bound)")
    for key, text in SOURCES.items():
        print(f"source {key}: {text}")
    if not args.no_timing:
        count, wall, cpu = time_default_dataset()
        what = f"whole default dataset ({count} recordings x 12 s)"
        print(f"{what}: {wall:.1f} s wall, {cpu:.1f} s CPU")


if __name__ == "__main__":
    main()
