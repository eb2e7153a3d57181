"""The table of sweep designs: how each samples, how big it is, how it is analysed, what is drawn.

One entry per design (``grid``, ``lhs``, ``sobol``, ``morris``); adding a design
is adding an entry to :data:`DESIGNS`. Each entry says

- how it samples the unit cube (``None``: the full factorial of the axes'
  levels, :func:`~sdt_framework.explore.design.design_points`),
- its number of points, from the sweep file alone,
- what it demands of the sweep file (ranges rather than levels, a power of two),
- its sensitivity estimator (``None``: the ANOVA of a balanced full factorial,
  :mod:`~sdt_framework.explore.sensitivity`) and the indices it reports,
- the index the report ranks and draws (its headline).

This module sits below the sweep model: it reads a sweep through the
:class:`SweepDesign` protocol and never imports it.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np
from threadpoolctl import threadpool_limits

from ..errors import SDTError

__all__ = ["DESIGNS", "Design", "SweepDesign", "salib_problem"]


class SweepDesign(Protocol):
    """What a design reads of a sweep (a :class:`~sdt_framework.explore.sweep.Sweep`)."""

    design: str
    samples: int
    levels: int
    seed: int
    axes: Mapping[str, Any]


def salib_problem(sweep: SweepDesign) -> dict:
    """SALib's problem definition: every axis on the unit interval."""
    names = list(sweep.axes)
    return {"num_vars": len(names), "names": names, "bounds": [[0.0, 1.0]] * len(names)}


@dataclass(frozen=True)
class Design:
    """One sweep design: sampling, size, requirements, estimator and headline index."""

    name: str
    method: str  # the sensitivity.csv ``method`` of its indices
    headline: str  # the index the report ranks and draws
    size: Callable[[SweepDesign], int]
    sample: Callable[[SweepDesign], np.ndarray] | None = None  # unit cube; None: factorial
    analyse: Callable[[SweepDesign, np.ndarray, np.ndarray], dict] | None = None  # None: ANOVA
    indices: Mapping[str, str | None] | None = None  # index -> its CI half-width in the result
    needs_ranges: bool = False
    power_of_two: bool = False
    min_samples: int = 1  # and why fewer cannot be analysed
    min_samples_why: str = ""
    min_axes: int = 1
    min_axes_why: str = ""


def _salib(sweep: SweepDesign, draw: Callable[[], np.ndarray]) -> np.ndarray:
    try:
        return draw()
    except ImportError:
        raise SDTError(
            f"design {sweep.design!r} needs SALib; install it with `pip install SALib`"
        ) from None


def _lhs(sweep: SweepDesign) -> np.ndarray:
    from scipy.stats import qmc

    return qmc.LatinHypercube(d=len(sweep.axes), seed=sweep.seed).random(sweep.samples)


def _sobol(sweep: SweepDesign) -> np.ndarray:
    def draw() -> np.ndarray:
        from SALib.sample import sobol

        problem = salib_problem(sweep)
        return sobol.sample(problem, sweep.samples, calc_second_order=False, seed=sweep.seed)

    return _salib(sweep, draw)


def _morris(sweep: SweepDesign) -> np.ndarray:
    def draw() -> np.ndarray:
        from SALib.sample import morris

        problem = salib_problem(sweep)
        return morris.sample(problem, sweep.samples, num_levels=sweep.levels, seed=sweep.seed)

    return _salib(sweep, draw)


def _quiet(analyse: Callable[[], Mapping[str, Any]]) -> dict:
    """A SALib analysis with what it says kept off the terminal, under ``"notices"``.

    SALib's delta analysis sets a warning filter of its own (``"once"``, which
    beats a caller's ``"ignore"``) and replaces ``warnings.formatwarning`` for
    the whole process; so the warnings are recorded rather than filtered, and
    the formatter is put back. numpy's warnings on degenerate effects (all
    equal) are recorded the same way. One BLAS thread: delta evaluates a Gaussian
    KDE per bootstrap sample, thousands of tiny solves that a thread per core only
    slows (benchmarks/bench_sensitivity.py: same indices, 38 s -> 0.6 s on a loaded 2-core machine).
    """
    formatter = warnings.formatwarning
    with warnings.catch_warnings(record=True) as caught, threadpool_limits(1, user_api="blas"):
        warnings.simplefilter("always")
        try:
            res = dict(analyse())
        finally:
            warnings.formatwarning = formatter
    res["notices"] = sorted({str(w.message).strip() for w in caught})
    return res


def _analyse_morris(sweep: SweepDesign, x: np.ndarray, y: np.ndarray) -> dict:
    from SALib.analyze import morris

    problem = salib_problem(sweep)
    return _quiet(lambda: morris.analyze(problem, x, y, num_levels=sweep.levels, seed=sweep.seed))


def _analyse_sobol(sweep: SweepDesign, x: np.ndarray, y: np.ndarray) -> dict:
    from SALib.analyze import sobol

    problem = salib_problem(sweep)
    return _quiet(lambda: sobol.analyze(problem, y, calc_second_order=False, seed=sweep.seed))


def _analyse_delta(sweep: SweepDesign, x: np.ndarray, y: np.ndarray) -> dict:
    from SALib.analyze import delta

    res = _quiet(lambda: delta.analyze(salib_problem(sweep), x, y, seed=sweep.seed))
    res["delta"], res["delta_conf"] = res["delta_raw"], res["delta_raw_conf"]
    return res


def _grid_size(sweep: SweepDesign) -> int:
    return math.prod(
        len(axis.levels) if axis.levels is not None else axis.steps for axis in sweep.axes.values()
    )


#: design name -> its entry; the order is the order the sweep file's docs list them in
DESIGNS: dict[str, Design] = {
    "grid": Design("grid", method="anova", headline="share", size=_grid_size),
    "lhs": Design(
        "lhs",
        method="lhs",
        headline="delta",
        size=lambda sweep: sweep.samples,
        sample=_lhs,
        analyse=_analyse_delta,
        indices={"delta": "delta_conf", "S1": "S1_conf"},
    ),
    "sobol": Design(
        "sobol",
        method="sobol",
        headline="ST",
        size=lambda sweep: sweep.samples * (len(sweep.axes) + 2),
        sample=_sobol,
        analyse=_analyse_sobol,
        indices={"S1": "S1_conf", "ST": "ST_conf"},
        needs_ranges=True,
        power_of_two=True,
        min_axes=2,
        min_axes_why="with one axis Saltelli's sample draws every point twice (its AB matrix "
        "is B) and S1 = ST = 1 says nothing; add an axis, or use design = 'lhs' or 'grid'",
    ),
    "morris": Design(
        "morris",
        method="morris",
        headline="mu_star",
        size=lambda sweep: sweep.samples * (len(sweep.axes) + 1),
        sample=_morris,
        analyse=_analyse_morris,
        indices={"mu_star": "mu_star_conf", "sigma": None},
        needs_ranges=True,
        min_samples=2,
        min_samples_why="sigma, the spread of the elementary effects, needs at least two "
        "trajectories; raise samples",
    ),
}
