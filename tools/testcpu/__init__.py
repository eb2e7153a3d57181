"""Where the test suite's time goes: each test's CPU, its own and its child processes'.

The suite's time on two cores is its CPU over two, so a test that costs CPU,
in pytest's process or in the ``sdt`` commands, workers and servers it starts,
is what to look at first. Run it as a pytest plugin, then sum it up::

    .venv/bin/python -m pytest -q -n 2 --dist loadfile -p tools.testcpu.plugin --test-cpu=/tmp/cpu
    .venv/bin/python -m tools.testcpu /tmp/cpu --top 30

Each pytest process (every pytest-xdist worker) appends one JSON line per test to
``DIR/<worker>.jsonl``: its id, its CPU seconds in this process (``self``), in the
child processes that ended during it (``children``, as the kernel counts them:
a child's CPU arrives when it is waited for, and a server's when the server ends)
and its wall seconds.
"""

from __future__ import annotations
