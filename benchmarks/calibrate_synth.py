"""Calibration of the synthetic pump against published statistics of the real NLN-EMP data.

For every calibrated figure this prints the published value, the synthetic value
(seed 0, and the mean over ``--seeds`` seeds, since a published value is itself
one realisation of a run-to-run scatter), their ratio (seed mean / published)
and the source. The synthetic value is measured exactly as the source measured
the real archive:

- source A computed band RMS per 12 s acquisition with ``scipy.signal.welch``
  (4096-sample Hann segments) and the trapezoidal integral of the PSD over the
  band; its figures are run means over the acquisitions of a run;
- source B computed the overall RMS of ch1 per acquisition (its column
  ``vibration`` is RMS in g times 9810 / (2 pi 50) mm/s per g, divided back here);
- the paper's figures are checked by running the product's own SDT chain.

It also times the generation of the whole default dataset (all recordings).
The published values are summaries read from the sources (run means of 15-60
acquisitions each); docs/data.md lists them with their exact location.

Run: ``.venv/bin/python benchmarks/calibrate_synth.py [--seeds 5] [--markdown]``
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache

import numpy as np
from scipy import signal

from sdt_framework.chain import degrade
from sdt_framework.data import open_synthetic
from sdt_framework.data.synth import FS_HZ, generate_run
from sdt_framework.registry import build_registry

SOURCES = {
    "A": "felcoslop/TP_CONFIABILIDADE@e73e8a85 code/resultados/tabelas/features.csv",
    "B": "CYPHr007/PILAR@5252bc18 nln_emp_features.csv",
    "A+B": "A (1-9 kHz band) over B (overall), Motor-2 at 75 %",
    "P": "the paper (seed 000), section 2.2 and Fig. 2",
}
CHANNELS = {"Motor-4": ("ch1", "ch2", "ch5"), "Motor-2": ("ch1",)}


def band_rms(x: np.ndarray, lo: float, hi: float) -> float:
    """RMS in [lo, hi) Hz: Welch PSD (4096-sample Hann segments) integrated by trapezoids."""
    f, p = signal.welch(x - x.mean(), fs=FS_HZ, nperseg=4096)
    sel = (f >= lo) & (f < hi)
    return float(np.sqrt(np.trapezoid(p[sel], f[sel])))


def overall_rms(x: np.ndarray) -> float:
    return float(np.sqrt(np.mean(x * x)))


@dataclass(frozen=True)
class Synth:
    """Cached access to generated runs of one seed."""

    seed: int
    duration: float

    @cache  # noqa: B019 - a handful of instances, kept for the script's lifetime
    def run(self, machine: str, run: str, acquisitions: int = 1) -> dict[str, np.ndarray]:
        condition, level = run.rsplit(" ", 1)
        return generate_run(
            machine,
            condition,
            int(level),
            channels=CHANNELS[machine],
            acquisitions=acquisitions,
            duration_s=self.duration,
            seed=self.seed,
        )

    def value(self, machine: str, run: str, ch: str, measure: Callable, acq: int = 1) -> float:
        """Run mean over acquisitions of ``measure`` on channel ``ch``."""
        return float(np.mean([measure(x) for x in self.run(machine, run, acq)[ch]]))

    def values(self, machine: str, runs: list[str], ch: str, measure: Callable) -> np.ndarray:
        return np.array([self.value(machine, r, ch, measure) for r in runs])


def cv(values: np.ndarray) -> float:
    return float(np.std(values, ddof=1) / np.mean(values))


HEALTHY = ["healthy 1", "healthy 2", "healthy 3"]
LOW_200 = lambda x: band_rms(x, 10.0, 200.0)  # noqa: E731
LOW_300 = lambda x: band_rms(x, 10.0, 300.0)  # noqa: E731
HIGH = lambda x: band_rms(x, 1000.0, 9000.0)  # noqa: E731


def levels(name: str, n: int) -> list[str]:
    return [f"{name} {k}" for k in range(1, n + 1)]


def within_run_cv(s: Synth, machine: str, run: str, ch: str, measure: Callable) -> float:
    return cv(np.array([measure(x) for x in s.run(machine, run, 5)[ch]]))


def sdt_peak(s: Synth, sensor: str) -> float:
    """Peak |output| of ``sensor``'s chain for cavitation suction 4, ch1 (no noise)."""
    spec = build_registry().sensor(sensor)
    y, _ = degrade(s.run("Motor-4", "cavitation suction 4")["ch1"], FS_HZ, spec, noise=False)
    return float(np.abs(y).max())


def angular_vs_healthy(s: Synth) -> float:
    """Largest angular-misalignment run over the largest healthy run, ch1 10-300 Hz."""
    ang = s.values("Motor-4", levels("align angular", 5), "ch1", LOW_300)
    return float(ang.max() / s.values("Motor-4", HEALTHY, "ch1", LOW_300).max())


def ratio(s: Synth, machine: str, a: list[str], b: list[str], ch: str, m: Callable) -> float:
    return float(s.values(machine, a, ch, m).mean() / s.values(machine, b, ch, m).mean())


@dataclass(frozen=True)
class Figure:
    key: str
    what: str
    published: float
    source: str
    measure: Callable[[Synth], float]
    kind: str = "value"  # "value": ratio within 1.5; "at most"/"at least": a bound


M4, M2 = "Motor-4", "Motor-2"
UM, UP, AP = levels("unbalance motor", 6), levels("unbalance pump", 3), levels("align parallel", 4)
BI, BO = levels("bearing bpfi", 3), levels("bearing bpfo", 3)
IMP, BP = levels("impeller", 3), levels("bearing pump", 3)
G = 9810.0 / (2 * np.pi * 50.0)  # source B's mm/s per g

FIGURES = [
    Figure("M4-h2", "M4 ch2 10-200 Hz, healthy mean (g)", 0.0486, "A",
           lambda s: s.values(M4, HEALTHY, "ch2", LOW_200).mean()),
    Figure("M4-h2cv", "M4 ch2 10-200 Hz, healthy run-to-run CV", 0.385, "A",
           lambda s: cv(s.values(M4, HEALTHY, "ch2", LOW_200))),
    Figure("M4-h5", "M4 ch5 10-200 Hz, healthy mean (g)", 0.0889, "A",
           lambda s: s.values(M4, HEALTHY, "ch5", LOW_200).mean()),
    Figure("M4-h5cv", "M4 ch5 10-200 Hz, healthy run-to-run CV", 0.045, "A",
           lambda s: cv(s.values(M4, HEALTHY, "ch5", LOW_200))),
    Figure("M4-h1", "M4 ch1 10-300 Hz, healthy mean (g)", 0.0937, "A",
           lambda s: s.values(M4, HEALTHY, "ch1", LOW_300).mean()),
    Figure("M4-h1cv", "M4 ch1 10-300 Hz, healthy run-to-run CV", 0.091, "A",
           lambda s: cv(s.values(M4, HEALTHY, "ch1", LOW_300))),
    Figure("M4-acv", "M4 ch5 10-200 Hz, acquisition-to-acquisition CV in healthy 1", 0.026, "A",
           lambda s: within_run_cv(s, M4, "healthy 1", "ch5", LOW_200)),
    Figure("M4-um1", "unbalance motor 1 / healthy, ch2 10-200 Hz", 0.776, "A",
           lambda s: ratio(s, M4, UM[:1], HEALTHY, "ch2", LOW_200)),
    Figure("M4-um6", "unbalance motor 6 / 1, ch2 10-200 Hz", 2.51, "A",
           lambda s: ratio(s, M4, UM[-1:], UM[:1], "ch2", LOW_200)),
    Figure("M4-up1", "unbalance pump 1 / healthy, ch5 10-200 Hz", 1.024, "A",
           lambda s: ratio(s, M4, UP[:1], HEALTHY, "ch5", LOW_200)),
    Figure("M4-up3", "unbalance pump 3 / 1, ch5 10-200 Hz", 1.146, "A",
           lambda s: ratio(s, M4, UP[-1:], UP[:1], "ch5", LOW_200)),
    Figure("M4-ap1", "align parallel 1 / healthy, ch1 10-300 Hz", 1.21, "A",
           lambda s: ratio(s, M4, AP[:1], HEALTHY, "ch1", LOW_300)),
    Figure("M4-ap4", "align parallel 4 / 1, ch1 10-300 Hz", 2.73, "A",
           lambda s: ratio(s, M4, AP[-1:], AP[:1], "ch1", LOW_300)),
    Figure("M4-aa", "align angular, largest run / largest healthy run, ch1 10-300 Hz", 1.0, "A",
           angular_vs_healthy, "at most"),
    Figure("M2-h", "M2 ch1 overall RMS, healthy mean (g)", 0.534, "B",
           lambda s: s.values(M2, HEALTHY, "ch1", overall_rms).mean()),
    Figure("M2-hcv", "M2 ch1 overall RMS, healthy run-to-run CV", 0.207, "B",
           lambda s: cv(s.values(M2, HEALTHY, "ch1", overall_rms))),
    Figure("M2-acv", "M2 ch1 overall RMS, acquisition-to-acquisition CV in healthy 1", 0.04, "B",
           lambda s: within_run_cv(s, M2, "healthy 1", "ch1", overall_rms)),
    Figure("M2-hf", "M2 ch1 healthy 1, 1-9 kHz RMS / overall RMS (real: at 75 %)", 0.96, "A+B",
           lambda s: s.value(M2, "healthy 1", "ch1", HIGH)
           / s.value(M2, "healthy 1", "ch1", overall_rms)),
    Figure("M2-bi1", "bearing bpfi 1 / healthy, ch1 overall", 0.887, "B",
           lambda s: ratio(s, M2, BI[:1], HEALTHY, "ch1", overall_rms)),
    Figure("M2-bi3", "bearing bpfi 3 / 1, ch1 overall", 1.34, "B",
           lambda s: ratio(s, M2, BI[-1:], BI[:1], "ch1", overall_rms)),
    Figure("M2-bo3", "bearing bpfo 3 / 1, ch1 overall", 1.13, "B",
           lambda s: ratio(s, M2, BO[-1:], BO[:1], "ch1", overall_rms)),
    Figure("M2-imp", "impeller (mean of 3) / healthy, ch1 overall", 0.75, "B",
           lambda s: ratio(s, M2, IMP, HEALTHY, "ch1", overall_rms)),
    Figure("M2-bp", "bearing pump (mean of 3) / healthy, ch1 overall", 0.91, "B",
           lambda s: ratio(s, M2, BP, HEALTHY, "ch1", overall_rms)),
    Figure("P-345", "cavitation suction 4 ch1 through ADXL345: peak / 16 g (clips)", 1.0, "P",
           lambda s: sdt_peak(s, "adxl345") / 16.0, "at least"),
    Figure("P-357", "cavitation suction 4 ch1 through ADXL357: peak / 40 g (no clip)", 1.0, "P",
           lambda s: sdt_peak(s, "adxl357") / 40.0, "at most"),
]


def verdict(fig: Figure, value: float) -> str:
    if fig.kind == "at most":
        return "ok" if value < fig.published else "OUT"
    if fig.kind == "at least":
        return "ok" if value >= fig.published else "OUT"
    r = value / fig.published
    return "ok" if 1 / 1.5 <= r <= 1.5 else "OUT"


def time_default_dataset() -> float:
    """Seconds to generate every recording of the default dataset (seed 0)."""
    start = time.perf_counter()
    for rec in open_synthetic().recordings():
        rec.load()
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5, help="seeds averaged (default 5)")
    parser.add_argument("--duration", type=float, default=12.0, help="s per acquisition")
    parser.add_argument("--markdown", action="store_true", help="print a Markdown table")
    parser.add_argument("--no-timing", action="store_true", help="skip the dataset timing")
    args = parser.parse_args()
    synths = [Synth(seed, args.duration) for seed in range(args.seeds)]
    rows = []
    for fig in FIGURES:
        vals = np.array([fig.measure(s) for s in synths])
        mean = float(vals.mean())
        bound = {"at most": "< ", "at least": ">= "}.get(fig.kind, "")
        rows.append(
            (fig.what, f"{bound}{fig.published:.3g}", f"{vals[0]:.3g}", f"{mean:.3g}",
             f"{mean / fig.published:.2f}", verdict(fig, mean), fig.source)
        )
    head = ("figure", "published", f"synth seed 0", f"synth mean {args.seeds} seeds",
            "ratio", "check", "source")
    if args.markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for row in rows:
            print("| " + " | ".join(row) + " |")
    else:
        widths = [max(len(r[i]) for r in [head, *rows]) for i in range(len(head))]
        for row in [head, *rows]:
            print("  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
    print(f"{sum(r[5] == 'ok' for r in rows)}/{len(rows)} figures within bounds "
          "(ratio within 1/1.5..1.5, or the stated bound)")
    for key, text in SOURCES.items():
        print(f"source {key}: {text}")
    if not args.no_timing:
        print(f"whole default dataset (260 recordings, 12 s each): {time_default_dataset():.1f} s")


if __name__ == "__main__":
    main()
