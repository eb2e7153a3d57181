"""What `sdt benchmark` and `sdt explore` print about a plan before running it.

Both check the plan's size first (:mod:`sdt_framework.bench.size_check`), then
print, one line each, the sensors and the (machine, scenario) cells the plan
leaves out. Imported by the commands when they run, so ``--help`` stays fast.
"""

from __future__ import annotations

from collections.abc import Collection
from typing import TYPE_CHECKING

from .common import err_console, shorten_labels

if TYPE_CHECKING:
    from ..bench import Plan

__all__ = ["print_skipped"]


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
