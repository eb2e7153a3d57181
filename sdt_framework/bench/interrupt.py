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

__all__ = ["InterruptWatch", "no_swallowed_interrupt", "watch_interrupts"]


@dataclass
class InterruptWatch:
    """How many SIGINTs arrived while a :func:`watch_interrupts` block was active."""

    count: int = 0

    @property
    def seen(self) -> bool:
        """Whether at least one SIGINT arrived."""
        return self.count > 0


@contextlib.contextmanager
def watch_interrupts() -> Iterator[InterruptWatch]:
    """Record SIGINTs during the block; each still raises ``KeyboardInterrupt``.

    A handler installed before (for example by a test harness) is called
    instead of raising; a SIGINT that was ignored (``SIG_IGN``, as for a
    background job of a non-interactive shell) stays ignored and unrecorded.
    """
    watch = InterruptWatch()
    if threading.current_thread() is not threading.main_thread():
        yield watch
        return
    previous = signal.getsignal(signal.SIGINT)
    if previous == signal.SIG_IGN:
        yield watch
        return

    def handler(signum: int, frame: FrameType | None) -> Any:
        watch.count += 1
        if callable(previous):
            return previous(signum, frame)
        raise KeyboardInterrupt

    signal.signal(signal.SIGINT, handler)
    try:
        yield watch
    finally:
        signal.signal(signal.SIGINT, previous)


@contextlib.contextmanager
def no_swallowed_interrupt() -> Iterator[None]:
    """Raise ``KeyboardInterrupt`` at the end of the block if a SIGINT arrived in it.

    Wrap any call that might catch ``KeyboardInterrupt`` and return as if it
    had finished (``MLPClassifier.fit``): its result is then never used.
    """
    with watch_interrupts() as watch:
        yield
    if watch.seen:
        raise KeyboardInterrupt("interrupted during a classifier fit")
