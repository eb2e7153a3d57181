"""What `sdt benchmark` and `sdt explore` do with a plan before running it.

Both refuse a plan estimated above an hour unless ``--yes`` is given (the
runs already stored in the folder do not count), and both print, one line
each, the sensors and the (machine, scenario) cells the plan leaves out.
Imported by the commands when they run, so ``--help`` stays fast.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from ..bench import estimate as sizes
from ..errors import SDTError
from .common import err_console

if TYPE_CHECKING:
    from ..bench.estimate import Estimate
    from ..bench.plan import Plan

__all__ = ["check_size", "print_skipped"]


def check_size(plan: Plan, out_dir: Path, yes: bool, what: str, advice: str) -> Estimate:
    """The plan's size estimate; above an hour without ``yes``, one line ending in ``advice``."""
    size = sizes.estimate(plan, stored_runs=len(list((out_dir / "runs").glob("*.json"))))
    if size.seconds > sizes.CONFIRM_ABOVE_SECONDS and not yes:  # looked up per call
        raise SDTError(f"this {what} is {size.line()}; {advice}")
    return size


def print_skipped(plan: Plan) -> None:
    """One line per sensor and per (machine, scenario) the plan leaves out, with the reason."""
    for name, reason in plan.skipped_sensors.items():
        err_console.print(f"skipped sensor {name}: {reason}", highlight=False)
    for (machine, scenario), reason in sorted(plan.skipped.items()):
        err_console.print(f"skipped {machine} / {scenario}: {reason}", highlight=False)
