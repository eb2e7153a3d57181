"""Before any work goes to a Dask cluster: can every worker do it as this machine would?

A worker with another sdt-framework or plugin version computes other results
(or none: a sensor its plugins lack cannot be built), and a worker that cannot
open the data files or write the feature cache fails task after task. Each is
found here, before the first task is sent, by running :func:`worker_facts`
on every worker and comparing with this process; the first worker with a
problem is named in one line (``SDTError``, exit status 2 through the CLI).

What is compared:

- the sdt-framework version and the name and version of every distribution
  providing ``sdt_framework`` entry points (plugins), missing or extra;
- every data file the plan's recordings read (their ``source``, as this
  machine spells it; the plan makes them absolute, so every worker needs the
  same paths: the same mounts or a shared filesystem);
- the feature cache folder, which every worker writes (shared cache).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from importlib import metadata as md
from typing import Any

from ..errors import SDTError

__all__ = ["check_workers", "software", "worker_facts"]

_GROUP = "sdt_framework"
_HINT = "every worker needs the same software and data paths (docs/scale.md)"


def software() -> dict[str, str]:
    """``{distribution: version}`` of sdt-framework and of every plugin distribution."""
    found = {"sdt-framework": _version("sdt-framework")}
    for ep in md.entry_points(group=_GROUP):
        if ep.dist is not None:
            found.setdefault(ep.dist.name.lower().replace("_", "-"), ep.dist.version)
    return found


def _version(name: str) -> str:
    try:
        return md.version(name)
    except md.PackageNotFoundError:
        return "not installed"


def _cache_problem(cache_dir: str) -> str | None:
    try:
        os.makedirs(cache_dir, exist_ok=True)
    except OSError as exc:
        return f"cannot create the feature cache {cache_dir} ({exc.strerror or exc})"
    if not os.access(cache_dir, os.W_OK | os.X_OK):
        return f"cannot write the feature cache {cache_dir}"
    return None


def worker_facts(paths: list[str], cache_dir: str) -> dict[str, Any]:
    """Run on a worker: its software, the ``paths`` it cannot read, and its cache problem."""
    unreadable = [p for p in paths if not os.access(p, os.R_OK)]
    return {
        "software": software(),
        "unreadable": unreadable,
        "cache": _cache_problem(cache_dir) if cache_dir else None,
        "host": os.uname().nodename,
    }


def _differences(mine: dict[str, str], theirs: dict[str, str]) -> list[str]:
    out = []
    for name in sorted(set(mine) | set(theirs)):
        here, there = mine.get(name), theirs.get(name)
        if there is None:
            out.append(f"lacks {name} {here} (installed here)")
        elif here is None:
            out.append(f"has {name} {there}, not installed here")
        elif here != there:
            out.append(f"has {name} {there}, here {here}")
    return out


def _problem(facts: Any, mine: dict[str, str], paths: list[str]) -> str | None:
    if isinstance(facts, BaseException):  # e.g. sdt-framework not importable there
        return f"cannot run sdt-framework ({type(facts).__name__}: {facts})".replace("\n", " ")
    found = _differences(mine, facts["software"])
    if found:
        return "; ".join(found)
    unreadable = facts["unreadable"]
    if unreadable:
        more = f" (and {len(unreadable) - 1} more of {len(paths)})" if len(unreadable) > 1 else ""
        return f"cannot open data file {unreadable[0]}{more}"
    return facts["cache"]


def check_workers(client: Any, sources: Iterable[str], cache_dir: str = "") -> int:
    """Raise ``SDTError`` naming the first worker that differs; return the workers checked.

    ``sources`` are the recordings' sources (``"synthetic"`` and other non-files
    are not checked: they are generated on the worker).
    """
    paths = sorted({s for s in sources if os.path.isfile(s)})
    facts = client.run(worker_facts, paths, cache_dir, on_error="return")
    if not facts:
        raise SDTError("the Dask cluster has no workers; start some or leave --scheduler out")
    mine = software()
    for address in sorted(facts):
        problem = _problem(facts[address], mine, paths)
        if problem:
            host = facts[address]["host"] if isinstance(facts[address], dict) else "?"
            raise SDTError(f"Dask worker {address} (host {host}) {problem}; {_HINT}")
    return len(facts)
