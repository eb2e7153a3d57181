"""Whether a planned benchmark may start: it must fit, and a long one must be agreed to.

The plan is estimated first (:mod:`~sdt_framework.bench.estimate`: runs, time,
peak memory and disk). A plan whose recordings cannot be windowed, whose
memory is more than this machine has available or whose files are more than
the disk's free space is refused whatever the caller agreed to (it cannot
finish); one estimated above an hour is refused unless ``yes`` (the runs
already stored in the folder do not count). Nothing is created by the check.
``sdt benchmark``, ``sdt explore`` and :func:`~sdt_framework.bench.job.run_plan_folder`
all check through here, so they refuse the same plans with the same lines.
"""

from __future__ import annotations

import os
from pathlib import Path

from ..errors import SDTError
from . import estimate as sizes
from .estimate import Estimate
from .plan import Plan

__all__ = ["check_estimate", "check_size", "stored_runs"]


def stored_runs(out_dir: str | os.PathLike[str]) -> int:
    """Runs already finished in ``out_dir`` (a resume does not redo them)."""
    return len(list((Path(out_dir) / "runs").glob("*.json")))


def check_estimate(
    size: Estimate,
    out_dir: str | os.PathLike[str],
    yes: bool,
    what: str,
    reduce: str,
    verb: str = "start",
) -> None:
    """Refuse ``size`` if it cannot fit in memory or on disk; above an hour, ask for ``yes``.

    ``what`` names the work (``benchmark``, ``sweep of 10 points``) and
    ``reduce`` what makes it smaller; a long one is told to ``add --yes to
    <verb> it, or <reduce>``.
    """
    problem = sizes.memory_problem(size)
    if problem is not None:
        raise SDTError(f"this {what} is {size.line()} and {problem}; {reduce}")
    problem = sizes.disk_problem(size, out_dir)
    if problem is not None:
        raise SDTError(
            f"this {what} is {size.line()} and {problem}; free some space or choose "
            f"another --out, or {reduce}"
        )
    if size.seconds > sizes.CONFIRM_ABOVE_SECONDS and not yes:  # looked up per call
        raise SDTError(f"this {what} is {size.line()}; add --yes to {verb} it, or {reduce}")


def check_size(
    plan: Plan,
    out_dir: str | os.PathLike[str],
    yes: bool,
    what: str,
    reduce: str,
    verb: str = "start",
) -> Estimate:
    """The plan's estimate, checked by :func:`check_estimate` (``--units`` named when set)."""
    size = sizes.estimate(plan, stored_runs=stored_runs(out_dir))
    problem = sizes.recording_problem(plan, size)
    if problem is not None:  # the data itself, not the amount of work asked for
        raise SDTError(f"this {what} cannot run: {problem}")
    units = plan.config.units
    if units is not None and units > 1:
        what = f"{what} with --units {units}"
        reduce = f"lower --units, or {reduce}"
    check_estimate(size, out_dir, yes, what, reduce, verb)
    return size
