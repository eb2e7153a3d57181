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
"""

from __future__ import annotations

from ..bench.estimate import Estimate, estimate_like
from ..bench.plan import Plan
from ..specs import SensorSpec
from .designs import DESIGNS
from .sweep import Sweep

__all__ = ["POINT_BYTES", "POINT_SECONDS", "design_size", "sweep_estimate"]

#: memory of one built point (design row, validated profile, registry entry), rounded up
POINT_BYTES = 10_000
#: time to build one point, rounded up
POINT_SECONDS = 1e-4


def design_size(sweep: Sweep) -> int:
    """Number of design points of ``sweep``, exact, without building any of them."""
    return DESIGNS[sweep.design].size(sweep)


def sweep_estimate(probe: Plan, base: SensorSpec, points: int) -> Estimate:
    """The sweep's estimate: ``points`` sensors costed as ``base``, plus the reference and base.

    ``probe`` is the sweep's protocol planned on any sensors: only its data,
    classifiers and options are read.
    """
    size = estimate_like(probe, base, points + 2)
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
