"""How big a sweep is, known from the sweep file alone, before its design is built.

A design's number of points is arithmetic on the file: the product of the
axes' level counts for ``grid`` (an explicit list's length, or ``steps``),
``samples`` for ``lhs``, ``samples * (d + 2)`` for ``sobol`` (Saltelli, first
and total indices) and ``samples * (d + 1)`` for ``morris``. A ``10^8``-point
grid is therefore refused (or asked ``--yes`` for) without allocating one of
its rows.

What each point costs is what one sensor costs in the benchmark that
evaluates it (:func:`~sdt_framework.bench.estimate.estimate_like`, costed as
the base sensor), plus building it: its design row, its validated profile in
the registry. Measured with ``resource.getrusage`` around
:func:`~sdt_framework.explore.design.design_points`,
:func:`~sdt_framework.explore.points.build_points` and ``registry.add`` on
grids of 2 000 and 10 000 points: 5.4 to 9.1 kB and 0.04 to 0.07 ms a point.

The benchmark's estimate counts the chains, features and classifiers only.
A sweep's run also reads (or, for the synthetic default, generates) every
recording, starts its worker processes and writes its report; those were
what a printed "3 s" left out of a sweep that took over a minute. Measured
phase by phase (``time.process_time``, ``--jobs 1``) on a sobol sweep of 4
points over the quick preset's 260 recordings (20.8 M samples): the
benchmark's estimate 7 s; the run 20 s on a cold cache, 12.5 s on a warm one
(13 s beyond the estimate either way: the recordings, close to the 1.5 M
samples/s of ``sdt_framework.data.sizes.SYNTH_SAMPLES_PER_S``); imports of a
process 2.5-2.7 s; the report 16 s. :func:`run_estimate` adds these, and
:func:`assumptions` says so on the printed line.
"""

from __future__ import annotations

from dataclasses import replace

from ..bench.estimate import Estimate, estimate, estimate_like, format_duration
from ..bench.plan import Plan
from ..data.sizes import SYNTH_SAMPLES_PER_S
from ..specs import SensorSpec
from .designs import DESIGNS
from .sweep import Sweep

__all__ = [
    "POINT_BYTES",
    "POINT_SECONDS",
    "REPORT_SECONDS",
    "START_SECONDS",
    "adaptive_estimate",
    "assumptions",
    "design_size",
    "exhaustive_estimate",
    "run_estimate",
    "sweep_estimate",
]

#: memory of one built point (design row, validated profile, registry entry), rounded up
POINT_BYTES = 10_000
#: time to build one point, rounded up
POINT_SECONDS = 1e-4
#: time for a process to start (imports), measured 2.5-2.7 s, rounded up
START_SECONDS = 3.0
#: time to write report.md/report.html with the exploration figures, measured 16 s, rounded up
REPORT_SECONDS = 20.0


def design_size(sweep: Sweep) -> int:
    """Number of design points of ``sweep``, exact, without building any of them."""
    return DESIGNS[sweep.design].size(sweep)


def sweep_estimate(probe: Plan, base: SensorSpec, points: int) -> Estimate:
    """The sweep's estimate: ``points`` sensors costed as ``base``, plus the reference and base.

    ``probe`` is the sweep's protocol planned on any sensors: only its data,
    classifiers and options are read.
    """
    size = run_estimate(probe, estimate_like(probe, base, points + 2), report=True)
    return Estimate(
        size.runs,
        size.runs_to_do,
        size.feature_draws,
        size.seconds + points * POINT_SECONDS,  # built in this one process
        size.workers,
        size.memory_bytes + points * POINT_BYTES,
        size.disk_bytes,
        size.fixed_bytes,
    )


def _extra(plan: Plan, size: Estimate, report: bool) -> dict[str, float]:
    """What a sweep's run costs beyond the benchmark's estimate, by phase (seconds)."""
    samples = sum(r.total_samples for r in plan.recordings)
    extra = {
        "recordings read or generated": samples / SYNTH_SAMPLES_PER_S / size.workers,
        "process start": START_SECONDS,
    }
    if report:
        extra["report"] = REPORT_SECONDS
    return extra


def run_estimate(plan: Plan, size: Estimate, report: bool) -> Estimate:
    """``size`` (the benchmark's estimate of ``plan``) plus reading the recordings, starting
    the processes and, when ``report``, writing the report."""
    if size.runs_to_do == 0:
        return size  # nothing left to run: a resume only writes the tables
    return replace(size, seconds=size.seconds + sum(_extra(plan, size, report).values()))


def exhaustive_estimate(plan: Plan, report: bool, stored_runs: int = 0) -> Estimate:
    """The exhaustive strategy's estimate: the benchmark's of ``plan`` (``stored_runs``
    already done in the folder) plus what the sweep's run adds (:func:`run_estimate`)."""
    return run_estimate(plan, estimate(plan, stored_runs=stored_runs), report)


def assumptions(plan: Plan, benchmark: Estimate, report: bool) -> str:
    """What the printed estimate is made of and assumes, for the line under it."""
    if benchmark.runs_to_do == 0:
        return "nothing left to run"
    parts = [f"chains, features and classifiers {format_duration(benchmark.seconds)}"]
    parts += [f"{k} {format_duration(v)}" for k, v in _extra(plan, benchmark, report).items()]
    return (
        f"estimate = {' + '.join(parts)}; it assumes a cold feature cache and an otherwise "
        f"idle machine (a loaded one takes longer)"
    )


def adaptive_estimate(
    screen: Plan, full: Plan, base: SensorSpec, points: int, rounds: int, report: bool
) -> tuple[Estimate, Estimate]:
    """The adaptive strategy's two parts: the screen, and the full protocol at most.

    ``screen`` is the screen protocol on every point; ``full`` the sweep's
    protocol (only its data and options are read), run on at most ``points``
    line points plus the reference and base, costed as the base, in at most
    ``rounds`` rounds, each of which reads the recordings and starts its
    processes again (a round's earlier runs are copied, never redone).
    """
    first = run_estimate(screen, estimate(screen), report=False)
    refine = estimate_like(full, base, points + 2)
    extra = rounds * sum(_extra(full, refine, report=False).values())
    extra += REPORT_SECONDS if report else 0.0
    return first, replace(refine, seconds=refine.seconds + extra)
