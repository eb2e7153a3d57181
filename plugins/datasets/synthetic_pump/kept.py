"""Generated runs kept in this process for the next read, up to a memory budget.

A benchmark reads a run one channel (one recording) at a time, and the channels of a run
are generated together (they share their sources). The dataset used to keep only its
own last run, so a process generated a run again for every benchmark, sweep point or
notebook cell that read it, and a worker of ``--jobs N``, which unpickles its own copy of
the dataset with each task, generated it again for each of its channels. Runs are kept
here instead, for the process, by every argument of :func:`~.generate.generate_run`, in
sdt's memory-bounded store (:class:`~sdt_framework.signals.parsed.Kept`): the least
recently used go first while the kept runs and the next one would hold more than
:data:`KEEP_BYTES` (a run's size is known before it is generated), so they hold at most
that, or the one run being read where it is larger (as before). Kept arrays are
read-only: a reader that wrote into one would change what the next one gets.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable

import numpy as np

from sdt_framework.signals.parsed import Kept

__all__ = ["KEEP_BYTES", "RUNS", "kept_run"]

#: generated samples kept in a process beside the run being read, bytes
KEEP_BYTES = 64_000_000

#: the kept runs of this process
RUNS: Kept[dict[str, np.ndarray]] = Kept(
    KEEP_BYTES, lambda run: sum(x.nbytes for x in run.values())
)


def kept_run(
    key: Hashable, nbytes: int, generate: Callable[[], dict[str, np.ndarray]]
) -> dict[str, np.ndarray]:
    """The run ``key`` names: kept, or ``generate()``-d (``nbytes`` of arrays) and kept."""

    def read_only() -> dict[str, np.ndarray]:
        run = generate()
        for x in run.values():
            x.setflags(write=False)
        return run

    return RUNS.get(key, read_only, size=nbytes)
