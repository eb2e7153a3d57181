"""How many local worker processes a benchmark starts: what can help, never more.

Every task (one recording's features, one classifier run) runs in one process
on one BLAS thread, so processes beyond the cores only take turns on them, and
processes beyond the tasks have nothing to do; each still costs its start-up
and about 250 MB of memory. ``--jobs 1000`` on 2 cores started 1000 loky workers
(a load of 77; the machine stopped answering) while the estimate said
"2 processes". The pool is therefore capped at :data:`PROCESSES_PER_CORE` per
core (a second process per core keeps it busy while the other reads a file or
waits for its result to be sent) and at the tasks; a capped ``--jobs`` gets
one note (:func:`pool_note`), and the estimate counts the processes started.

The cores are joblib's count (the CPUs this process may use: affinity and a
container's CPU quota included).
"""

from __future__ import annotations

from joblib import cpu_count

__all__ = ["PROCESSES_PER_CORE", "cores", "pool_note", "pool_size"]

#: at most this many local worker processes per core
PROCESSES_PER_CORE = 2


def cores() -> int:
    """The CPUs this process may use."""
    return max(1, int(cpu_count()))


def pool_size(requested: int, tasks: int | None = None) -> int:
    """Processes to start for ``requested`` (``--jobs``) and at most ``tasks`` tasks at once."""
    size = min(requested, PROCESSES_PER_CORE * cores())
    if tasks is not None:
        size = min(size, tasks)
    return max(1, size)


def pool_note(requested: int, tasks: int) -> str | None:
    """One line saying why fewer than ``requested`` processes start, or None if all do."""
    size = pool_size(requested, tasks)
    if size >= requested:
        return None
    n = cores()
    if size == tasks:
        why = f"the benchmark has {tasks} task{'s' if tasks > 1 else ''} to run at once"
    else:
        why = (
            f"{n} core{'s' if n > 1 else ''} here; more than {PROCESSES_PER_CORE} processes "
            f"per core only take turns on them"
        )
    return f"--jobs {requested}: starting {size} process{'es' if size > 1 else ''} ({why})"
