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
from ..signals import sizes as host
from ..signals.sizes import human_bytes
from . import estimate as sizes
from .estimate import CHAIN_BYTES_PER_SAMPLE, PROCESS_BYTES, Estimate
from .plan import Plan

__all__ = [
    "check_estimate",
    "check_size",
    "disk_problem",
    "memory_problem",
    "recording_problem",
    "stored_runs",
    "unfit",
]


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
    problem = memory_problem(size)
    if problem is not None:
        raise SDTError(f"this {what} is {size.line()} and {problem}; {reduce}")
    problem = disk_problem(size, out_dir)
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
    problem = recording_problem(plan, size)
    if problem is not None:  # the data itself, not the amount of work asked for
        raise SDTError(f"this {what} cannot run: {problem}")
    units = plan.config.units
    if units is not None and units > 1:
        what = f"{what} with --units {units}"
        reduce = f"lower --units, or {reduce}"
    check_estimate(size, out_dir, yes, what, reduce, verb)
    return size


def unfit(size: Estimate, out_dir: str | os.PathLike[str] | None = None) -> str | None:
    """Why ``size`` cannot run on this machine (memory, or disk under ``out_dir``), or None."""
    return memory_problem(size) or (disk_problem(size, out_dir) if out_dir is not None else None)


def memory_problem(size: Estimate) -> str | None:
    """``needs about X of memory, more than the Y available``, or None if it fits."""
    room = host.available_memory()  # looked up per call (tests replace it)
    if size.memory_bytes <= room:
        return None
    return (
        f"needs about {human_bytes(size.memory_bytes)} of memory, more than the "
        f"{human_bytes(room)} available"
    )


def recording_problem(plan: Plan, size: Estimate) -> str | None:
    """Why the plan's largest recording alone cannot be processed here (naming its file), or None.

    When the part of the memory that no setting but the data changes (each
    process running a chain on the largest recording) is more than is
    available, fewer repetitions, sensors or classifiers cannot help: the
    recording is named with its file's size, and what would.
    """
    room = host.available_memory()
    if size.fixed_bytes <= room or not plan.recordings:
        return None
    largest = max(plan.recordings, key=lambda r: r.total_samples)
    samples = largest.total_samples
    try:
        on_disk = f", {human_bytes(os.stat(largest.source).st_size)}"
    except (OSError, ValueError):  # generated data: no file
        on_disk = ""
    one = PROCESS_BYTES + CHAIN_BYTES_PER_SAMPLE * samples
    fewer = ""
    if size.workers > 1 and one <= room:
        fewer = f", or use --jobs 1 (one process needs about {human_bytes(one)})"
    return (
        f"recording {largest.recording_id} ({largest.source}{on_disk}) is {samples:,} samples; "
        f"running it through a sensor chain needs about "
        f"{human_bytes(CHAIN_BYTES_PER_SAMPLE * samples)} of memory in each of {size.workers} "
        f"process{'es' if size.workers > 1 else ''}, more than the {human_bytes(room)} "
        f"available; split it into shorter recordings{fewer}"
    )


def disk_problem(size: Estimate, out_dir: str | os.PathLike[str]) -> str | None:
    """``writes about X, more than the Y free on the disk of <out_dir>``, or None if it fits."""
    free = host.free_disk(Path(out_dir))
    if size.disk_bytes <= free:
        return None
    return (
        f"writes about {human_bytes(size.disk_bytes)}, more than the {human_bytes(free)} "
        f"free on the disk of {out_dir}"
    )
