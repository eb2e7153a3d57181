"""What a computation will cost, known before anything is allocated.

A command whose size a user chooses (``sdt validate-noise --windows``,
``sdt dataset synth --duration``) estimates its peak memory, disk output and
run time from the sizes alone, compares them with what this machine has, and
refuses or asks for ``--yes`` before allocating (the policy is in
``sdt_framework.cli.guards``). Here: what this machine has (memory a new
allocation can use, free disk), the :class:`Cost` of a computation, sizes
written for people, and :func:`building`, which names what was being built
when memory ran out. The measured costs of each computation live beside it
(:mod:`.file_sizes` for signal files, ``sdt_framework.data.sizes`` for the
synthetic generator).
"""

from __future__ import annotations

import contextlib
import os
import shutil
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "Cost",
    "available_memory",
    "building",
    "free_disk",
    "human_bytes",
    "human_seconds",
    "memory_cause",
]

_CAUSE = "sdt_building"  # attribute of a MemoryError: (what was being built, what to do)


@contextlib.contextmanager
def building(what: str, reduce: str) -> Iterator[None]:
    """Name what is being built, should memory run out inside (``memory_cause`` reads it).

    ``what`` completes "out of memory while ..." (``"building the sweep design
    of 40 points"``); ``reduce`` says what makes it smaller. The innermost
    ``building`` names it: the most precise cause wins.
    """
    try:
        yield
    except MemoryError as exc:
        if getattr(exc, _CAUSE, None) is None:
            setattr(exc, _CAUSE, (what, reduce))
        raise


def memory_cause(exc: MemoryError) -> tuple[str, str] | None:
    """(what was being built, what to do) when memory ran out, if a ``building`` said."""
    cause = getattr(exc, _CAUSE, None)
    return cause if isinstance(cause, tuple) else None


@dataclass(frozen=True)
class Cost:
    """Estimated size of a computation: samples, peak memory, disk output, run time."""

    samples: int
    memory_bytes: int
    seconds: float
    disk_bytes: int = 0


def human_bytes(n: float) -> str:
    """``1.5 GB``-style size (decimal units, as ``df -H``)."""
    for unit in ("B", "kB", "MB", "GB", "TB", "PB"):
        if abs(n) < 1000 or unit == "PB":
            return f"{n:.0f} {unit}" if unit == "B" else f"{n:.1f} {unit}"
        n /= 1000
    raise AssertionError("unreachable")


def human_seconds(s: float) -> str:
    """``45 s``, ``12 min``, ``3.5 h`` or ``2.0 days``."""
    if s < 120:
        return f"{s:.0f} s"
    if s < 7200:
        return f"{s / 60:.0f} min"
    if s < 172800:
        return f"{s / 3600:.1f} h"
    return f"{s / 86400:.1f} days"


def _cgroup_room() -> int | None:
    """Bytes left under a cgroup v2 memory limit (containers), None when unlimited."""
    try:
        limit = Path("/sys/fs/cgroup/memory.max").read_text().strip()
        used = int(Path("/sys/fs/cgroup/memory.current").read_text())
    except (OSError, ValueError):
        return None
    return None if limit == "max" else max(0, int(limit) - used)


def _address_space_room() -> int | None:
    """Bytes left under this process's address-space limit (``ulimit -v``), None if unlimited.

    The limit caps the process's virtual size (``VmSize``), so what is left is
    the limit less that size: an allocation above it fails with MemoryError
    however much memory the machine has free.
    """
    try:
        import resource
    except ImportError:  # not POSIX
        return None
    soft = resource.getrlimit(resource.RLIMIT_AS)[0]
    if soft == resource.RLIM_INFINITY:
        return None
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("VmSize:"):
                return max(0, soft - int(line.split()[1]) * 1024)
    except (OSError, ValueError, IndexError):
        pass
    return soft


def available_memory() -> int:
    """Bytes of memory a new allocation can use now (``MemAvailable``, cgroup limit,
    address-space limit)."""
    room = None
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemAvailable:"):
                room = int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        room = None
    if room is None:
        try:
            room = os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
        except (ValueError, OSError, AttributeError):
            room = 2**63 - 1  # unknown: do not refuse on a guess
    limits = [x for x in (_cgroup_room(), _address_space_room()) if x is not None]
    return min([room, *limits])


def free_disk(path: Path) -> int:
    """Free bytes on the file system that will hold ``path`` (its nearest existing folder).

    Unknown (a huge number) when it cannot be asked, or for a pseudo file
    system of size 0, so that the write's own error names the real cause.
    """
    folder = Path(os.path.abspath(path))
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    try:
        usage = shutil.disk_usage(folder)
    except OSError:
        return 2**63 - 1  # unknown: the write itself reports a full disk
    # a file system of no size (sysfs, procfs) is no disk: writing there fails on its own
    return usage.free if usage.total else 2**63 - 1
