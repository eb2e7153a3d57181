"""The progress bar of long commands (benchmark, explore): one bar per stage."""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from typing import Any

from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeRemainingColumn

from .common import console

__all__ = ["Bars", "progress_bar"]


def _columns() -> tuple[Any, ...]:
    return (
        TextColumn("{task.description:>9}"),
        BarColumn(),
        MofNCompleteColumn(),
        TimeRemainingColumn(),
    )


class Bars:
    """``progress(stage, done, total)`` drawing a rich bar per stage, from its first call
    until :meth:`close` (a command's lines before the first call print above the bars,
    those after ``close`` below them)."""

    def __init__(self) -> None:
        self._bar: Progress | None = None
        self._tasks: dict[str, Any] = {}

    def __call__(self, stage: str, done: int, total: int) -> None:
        if self._bar is None:
            self._bar = Progress(*_columns(), console=console, transient=False)
            self._bar.start()
        if stage not in self._tasks:
            self._tasks[stage] = self._bar.add_task(stage, total=total)
        self._bar.update(self._tasks[stage], completed=done, total=total)

    def close(self) -> None:
        """Draw the bars one last time and stop; nothing if none was drawn (called again too)."""
        if self._bar is not None:
            self._bar.stop()
            self._bar = None


@contextlib.contextmanager
def progress_bar() -> Iterator[Callable[[str, int, int], None]]:
    """Yield a :class:`Bars` callback, closed when the block ends."""
    bars = Bars()
    try:
        yield bars
    finally:
        bars.close()
