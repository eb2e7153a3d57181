"""What `sdt benchmark` and `sdt explore` do with a plan before running it.

Both estimate the plan first (:mod:`sdt_framework.bench.estimate`: runs, time,
peak memory and disk), then refuse a plan whose memory is more than this
machine has available or whose files are more than the disk's free space
(even with ``--yes``: it cannot finish), and one estimated above an hour
unless ``--yes`` is given (the runs already stored in the folder do not
count). Nothing is created before the check. Both print, one line each, the
sensors and the (machine, scenario) cells the plan leaves out. Imported by
the commands when they run, so ``--help`` stays fast.
"""

from __future__ import annotations

from collections.abc import Collection
from pathlib import Path
from typing import TYPE_CHECKING

from ..bench import estimate as sizes
from ..errors import SDTError
from .common import err_console, shorten_labels

if TYPE_CHECKING:
    from ..bench.estimate import Estimate
    from ..bench.plan import Plan

__all__ = ["check_estimate", "check_size", "print_skipped", "stored_runs"]


def stored_runs(out_dir: Path) -> int:
    """Runs already finished in ``out_dir`` (a resume does not redo them)."""
    return len(list((out_dir / "runs").glob("*.json")))


def check_estimate(
    size: Estimate, out_dir: Path, yes: bool, what: str, reduce: str, verb: str = "start"
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
    plan: Plan, out_dir: Path, yes: bool, what: str, reduce: str, verb: str = "start"
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


#: skipped data files named one per line; the rest counted (summary.json lists all)
_SHOWN_FILES = 5


def print_skipped(plan: Plan, shown: Collection[str] = ()) -> None:
    """One line per sensor and per (machine, scenario) the plan leaves out, with the reason.

    Sensors named in ``shown`` were already reported (as skipped sweep points).
    """
    for name, reason in plan.skipped_sensors.items():
        if name not in shown:
            err_console.print(shorten_labels(f"skipped sensor {name}: {reason}"), highlight=False)
    for (machine, scenario), reason in sorted(plan.skipped.items()):
        line = shorten_labels(f"skipped {machine} / {scenario}: {reason}")
        err_console.print(line, highlight=False, soft_wrap=True)
    files = plan.dataset.skipped
    for item in files[:_SHOWN_FILES]:
        line = shorten_labels(f"skipped {item.path}: {item.reason}")
        err_console.print(line, highlight=False, soft_wrap=True)
    if len(files) > _SHOWN_FILES:
        err_console.print(
            f"skipped {len(files) - _SHOWN_FILES} more files or folders (all listed in "
            f"summary.json, dataset_skipped)",
            highlight=False,
        )
