"""Ctrl-C that no library can swallow.

scikit-learn's ``MLPClassifier`` catches ``KeyboardInterrupt`` inside ``fit``,
warns "Training interrupted by user" and returns a half-trained model; stored
as an ordinary result, that model would be a wrong number kept for good.
:func:`watch_interrupts` records every SIGINT that arrives while it is active
(and still raises ``KeyboardInterrupt`` as Python does by default), so a
caller can tell afterwards that an interrupt happened even if the code in
between swallowed it. :func:`no_swallowed_interrupt` turns such a recorded
interrupt back into ``KeyboardInterrupt`` when its block ends: an interrupted
fit never returns a result.

SIGTERM (``kill``, a batch scheduler's time limit, ``docker stop``) is treated
like Ctrl-C once a command asks for it (``watch_interrupts(terminate=True)``,
as ``sdt benchmark`` and ``sdt explore`` do): it raises :class:`Terminated`, a
``KeyboardInterrupt``, so every Ctrl-C path applies to it (nothing of an
unfinished run is stored, the worker pool is shut down, finished runs are
kept) and the command can still tell the two apart for its exit status (143
instead of 130). Without such a watch SIGTERM keeps its default action.

Python delivers signals to the main thread only; in any other thread (a Dask
worker's task threads) these helpers do nothing, and nothing there can see a
SIGINT either.
"""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from types import FrameType
from typing import Any

__all__ = ["InterruptWatch", "Terminated", "no_swallowed_interrupt", "watch_interrupts"]


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where a SIGINT raises ``KeyboardInterrupt`` (and caught with it)."""


@dataclass
class InterruptWatch:
    """How many SIGINTs (and SIGTERMs) arrived while a :func:`watch_interrupts` block was active."""

    count: int = 0
    #: whether one of them was a SIGTERM (the command then exits with 143, not 130)
    terminated: bool = False

    @property
    def seen(self) -> bool:
        """Whether at least one SIGINT or SIGTERM arrived."""
        return self.count > 0


def _watched(terminate: bool) -> list[signal.Signals]:
    """SIGINT, and SIGTERM when asked for or when an enclosing watch already handles it."""
    sigterm = signal.getsignal(signal.SIGTERM)
    return [signal.SIGINT] + ([signal.SIGTERM] if terminate or callable(sigterm) else [])


@contextlib.contextmanager
def watch_interrupts(terminate: bool = False) -> Iterator[InterruptWatch]:
    """Record SIGINTs during the block; each still raises ``KeyboardInterrupt``.

    With ``terminate`` a SIGTERM is recorded too and raises :class:`Terminated`;
    a watch nested in such a block records SIGTERMs as well. A handler
    installed before (for example by a test harness, or an enclosing watch) is
    called instead of raising; a signal that was ignored (``SIG_IGN``, as SIGINT
    for a background job of a non-interactive shell) stays ignored and unrecorded.
    """
    watch = InterruptWatch()
    if threading.current_thread() is not threading.main_thread():
        yield watch
        return
    previous = {s: signal.getsignal(s) for s in _watched(terminate)}
    previous = {s: h for s, h in previous.items() if h is not None and h != signal.SIG_IGN}

    def handler(signum: int, frame: FrameType | None) -> Any:
        watch.count += 1
        watch.terminated |= signum == signal.SIGTERM
        before = previous[signal.Signals(signum)]
        if callable(before):
            return before(signum, frame)
        if signum == signal.SIGTERM:
            raise Terminated("stopped by SIGTERM")
        raise KeyboardInterrupt

    for signum in previous:
        signal.signal(signum, handler)
    try:
        yield watch
    finally:
        for signum, before in previous.items():
            signal.signal(signum, before)


@contextlib.contextmanager
def no_swallowed_interrupt() -> Iterator[None]:
    """Raise ``KeyboardInterrupt`` at the end of the block if a SIGINT arrived in it
    (:class:`Terminated` for a SIGTERM, when an enclosing watch handles SIGTERM).

    Wrap any call that might catch ``KeyboardInterrupt`` and return as if it
    had finished (``MLPClassifier.fit``): its result is then never used.
    """
    with watch_interrupts() as watch:
        yield
    if watch.terminated:
        raise Terminated("terminated during a classifier fit")
    if watch.seen:
        raise KeyboardInterrupt("interrupted during a classifier fit")
