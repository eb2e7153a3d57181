"""Where tasks run: local processes (joblib/loky) or a Dask distributed cluster.

Both engines expose the same ``map_unordered(fn, items)`` so the orchestrator
has one code path; results stream back as they finish, which drives the
progress bar. Local workers are limited to one BLAS/OpenMP thread each so
``--jobs`` processes do not oversubscribe the cores (each fit also limits
itself, see :mod:`~sdt_framework.bench.classify`, so results never depend on
the engine).

A Dask scheduler address is checked before connecting: a malformed one, or
one that cannot be reached, is one clear error, never a traceback. Once
connected, every worker is checked (:mod:`.workers`) before any task is sent.

Ctrl-C belongs to the main process. A terminal delivers SIGINT to every
process of the foreground group, workers included; local workers therefore
ignore it (loky workers from their first task on, the processes of a
LocalCluster we start from their start-up), so an interrupted worker neither
returns a half-trained model nor floods the terminal with tracebacks. The
main process stops consuming results and shuts the pool down. Workers of a
cluster the user started (``--scheduler``) are left as they are.

A main process killed outright (SIGKILL, the out-of-memory killer) cannot shut
its pool down, and loky workers used to compute on for minutes. Each local
worker therefore watches its parent from its first task on
(:func:`exit_with_parent`) and ends within a second or two of it.
"""

from __future__ import annotations

import contextlib
import logging
import os
import signal
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from typing import Any, Protocol

from joblib import Parallel, delayed, parallel_config

from ..errors import SDTError
from .workers import check_workers

__all__ = [
    "DaskExecutor",
    "Executor",
    "LocalExecutor",
    "check_scheduler_address",
    "exit_with_parent",
    "open_executor",
]

#: how often a worker looks whether the main process still lives, seconds
PARENT_POLL_SECONDS = 0.5
#: this process's parent watch has started (a worker's own state, set in the worker)
_watching: list[int] = []


def exit_with_parent(parent: int) -> None:
    """End this process as soon as ``parent`` is no longer its parent (it died).

    A daemon thread polls ``os.getppid()`` (an orphan is re-parented to init
    or a subreaper): portable to every POSIX system, and unlike Linux's
    ``PR_SET_PDEATHSIG`` not fooled by loky starting workers from a helper
    thread of the parent. Started once per process; a parent already gone
    ends the process at once.
    """
    if _watching:
        return
    _watching.append(parent)

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(PARENT_POLL_SECONDS)
        os._exit(1)  # nothing of this worker's can be delivered any more

    threading.Thread(target=watch, name="sdt-parent-watch", daemon=True).start()


class Executor(Protocol):
    """Runs ``fn`` over ``items``, yielding results in completion order."""

    def map_unordered(self, fn: Callable[[Any], Any], items: Iterable[Any]) -> Iterator[Any]:
        """Apply ``fn`` to each item; yield each result as soon as it is ready."""
        ...


class _IgnoringInterrupts:
    """``fn`` run in a worker process that leaves Ctrl-C to the main process and ends with
    it (picklable)."""

    def __init__(self, fn: Callable[[Any], Any]) -> None:
        self.fn = fn
        self.main_pid = os.getpid()

    def __call__(self, item: Any) -> Any:
        if os.getpid() != self.main_pid:
            exit_with_parent(self.main_pid)
            if threading.current_thread() is threading.main_thread():
                signal.signal(signal.SIGINT, signal.SIG_IGN)
        return self.fn(item)


def _ignore_sigint_in_worker() -> None:
    """Run at a local Dask worker's start-up, in its main thread (signals live there)."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)


class LocalExecutor:
    """joblib processes on this machine (``jobs == 1`` runs in-process), never more than
    the items; joblib dispatches the items in the order given."""

    def __init__(self, jobs: int) -> None:
        self.jobs = jobs

    def map_unordered(self, fn: Callable[[Any], Any], items: Iterable[Any]) -> Iterator[Any]:
        items = list(items)
        jobs = min(self.jobs, len(items))  # a process without an item only costs its start
        if jobs <= 1:
            yield from map(fn, items)
            return
        task = _IgnoringInterrupts(fn)
        with parallel_config(backend="loky", inner_max_num_threads=1):
            yield from Parallel(n_jobs=jobs, return_as="generator_unordered")(
                delayed(task)(item) for item in items
            )


class DaskExecutor:
    """Tasks submitted to a ``distributed`` scheduler (a real cluster or a LocalCluster),
    started in the order given (the caller puts the longest first, :mod:`.schedule`)."""

    def __init__(self, client: Any) -> None:
        self.client = client

    def map_unordered(self, fn: Callable[[Any], Any], items: Iterable[Any]) -> Iterator[Any]:
        from distributed import as_completed

        items = list(items)
        # The scheduler orders tasks of equal priority by its own graph order, not by
        # submission: each task's priority is its place in ``items`` (first = highest).
        futures = [
            self.client.submit(fn, item, pure=False, priority=len(items) - i)
            for i, item in enumerate(items)
        ]
        for future in as_completed(futures):
            yield future.result()


_NETWORK_SCHEMES = ("tcp", "tls", "ws", "wss")


def check_scheduler_address(address: str) -> None:
    """Refuse a Dask scheduler address that cannot name a scheduler, with one line."""
    from distributed.comm import parse_address
    from distributed.comm.addressing import get_address_host_port
    from distributed.comm.registry import backends

    example = "e.g. tcp://192.168.1.10:8786"
    try:
        scheme, _ = parse_address(address)
        if scheme not in backends:
            known = ", ".join(sorted(backends))
            raise ValueError(f"unknown scheme {scheme[:12]!r}; known: {known}")
        if scheme in _NETWORK_SCHEMES:
            host, port = get_address_host_port(address)
            if not host or not 0 < port < 65536:
                raise ValueError("a host and a port between 1 and 65535 are needed")
    except (ValueError, TypeError) as exc:
        reason = str(exc).replace("\n", " ")[:120]
        raise SDTError(
            f"--scheduler {address!r} is not a Dask scheduler address ({reason}); {example}"
        ) from None


@contextlib.contextmanager
def open_executor(
    backend: str,
    jobs: int,
    scheduler: str | None,
    sources: Iterable[str] = (),
    cache_dir: str = "",
) -> Iterator[Executor]:
    """The executor for ``backend``; for Dask, connect to ``scheduler`` or start a local one.

    ``jobs`` is the local processes (or a local cluster's workers), already capped
    (:func:`~.pool.pool_size`).

    A Dask cluster's workers are checked before it is returned
    (:func:`~.workers.check_workers`: same software, every data file in ``sources``
    readable, ``cache_dir`` writable); a worker that differs is an ``SDTError``.
    """
    if backend == "local":
        yield LocalExecutor(jobs)
        return
    from distributed import Client, LocalCluster

    if scheduler:
        check_scheduler_address(scheduler)
        try:
            client = Client(scheduler, timeout="10s")
        except (OSError, ValueError, TypeError) as exc:
            reason = str(exc).replace("\n", " ")[:160]
            raise SDTError(
                f"cannot reach the Dask scheduler at {scheduler!r} ({reason}); start one with "
                f"`dask scheduler` or leave --scheduler out for a local cluster"
            ) from None
        with client:
            check_workers(client, sources, cache_dir)
            yield DaskExecutor(client)
        return
    with (
        LocalCluster(
            n_workers=jobs,
            threads_per_worker=1,
            # a free port: None still binds 8787 for the scheduler's HTTP routes, and a second
            # local cluster (two benchmarks at once) printed "UserWarning: Port 8787 is in use"
            dashboard_address=":0",
            silence_logs=logging.ERROR,  # shutting down after Ctrl-C is not worth a warning
        ) as cluster,
        Client(cluster) as client,
    ):
        client.run(_ignore_sigint_in_worker)
        check_workers(client, sources, cache_dir)
        yield DaskExecutor(client)
