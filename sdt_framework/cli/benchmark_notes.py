"""What ``sdt benchmark`` says before it starts, besides its estimate: one line each.

Each is a setting that does not do what its user may think, said before the
work rather than found out at its end:

- ``--jobs`` above what can help: fewer processes start (:mod:`sdt_framework.bench.pool`);
- ``--scheduler`` without ``--backend dask``: the address is not used;
- no reference among the sensors: ``sdt compare`` and the report's Verdict and
  Delta sections compare every sensor with the reference, and would find
  nothing to compare with only once every run is done;
- the plan's notes: speeds read off the spectrum for a feature set in orders.
"""

from __future__ import annotations

import shlex
from typing import TYPE_CHECKING

from ..bench import pool_note

if TYPE_CHECKING:
    from ..bench import Estimate, Plan

__all__ = ["start_lines"]


def start_lines(plan: Plan, size: Estimate) -> list[tuple[str, str]]:
    """``(label, message)`` of each line to print before the run (``note:``, ``warning:``)."""
    config = plan.config
    lines: list[tuple[str, str]] = [("note:", note) for note in plan.notes]
    local = config.backend == "local" or not config.scheduler
    if local and config.jobs != -1:  # -1 (all cores, the default) is never more than helps
        note = pool_note(config.jobs, max(len(plan.recordings), size.runs_to_do))
        if note is not None:
            lines.append(("note:", note))
    if config.scheduler and config.backend != "dask":
        lines.append(
            (
                "note:",
                f"--scheduler {config.scheduler} is not used: the backend is "
                f"{config.backend}; add --backend dask to send the work there",
            )
        )
    names = [s.name for s in plan.sensors]
    if plan.reference not in names:
        example = shlex.join(["--sensors", ",".join([plan.reference, *names])])
        lines.append(
            (
                "warning:",
                f"the reference {plan.reference} is not among the sensors ({', '.join(names)}): "
                f"sdt compare and the report's Verdict compare every sensor with it and will "
                f"have nothing to compare with; add it ({example}), or compare with one of "
                f"these later (sdt compare OUT --baseline {names[0]})",
            )
        )
    return lines
