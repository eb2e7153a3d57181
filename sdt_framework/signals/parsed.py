"""Values kept in this process for the next call, bounded by the memory they hold.

A text format (LVM, UFF) is parsed in full to scan, probe or read any one of its
signals, and a benchmark probes every file of a campaign before it reads the
first: a cache of the last file or two parsed every file of a campaign two or
three times. A generated dataset makes a whole run to read any one of its
channels. :class:`Kept` keeps the most recently used values while their arrays
hold at most ``keep_bytes``, and always the last one, however large (so a file
bigger than the bound is still parsed once for its scan, probe and read, as
before). :func:`keep_parsed` is its decorator form for a parse function.
"""

from __future__ import annotations

import functools
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any, Generic, TypeVar

__all__ = ["Kept", "keep_parsed"]

T = TypeVar("T")


class Kept(Generic[T]):
    """The most recently used values by (hashable) key, while ``nbytes`` of them sums to
    :attr:`keep_bytes` at most; the last one is kept whatever its size. Thread-safe.

    The key must name the value's content (a file's digest, or every argument of a
    generator): a changed file must be another key. A failed ``make`` keeps nothing.
    """

    def __init__(self, keep_bytes: int, nbytes: Callable[[T], int]) -> None:
        self.keep_bytes = keep_bytes
        self._nbytes = nbytes
        self._kept: OrderedDict[Hashable, tuple[T, int]] = OrderedDict()
        self._lock = threading.Lock()

    def __len__(self) -> int:
        return len(self._kept)

    @property
    def held(self) -> int:
        """Bytes the kept values hold."""
        with self._lock:
            return sum(size for _, size in self._kept.values())

    def get(self, key: Hashable, make: Callable[[], T], size: int | None = None) -> T:
        """The value kept for ``key``, or ``make()``'s, kept.

        ``size``, the bytes ``make()`` will hold when known beforehand: room is made
        before it runs, so the kept values and the new one never hold more than the
        bound together (unless the new one alone does). Otherwise room is made after.
        """
        with self._lock:
            if key in self._kept:
                self._kept.move_to_end(key)
                return self._kept[key][0]
            if size is not None:
                self._make_room(size)
        value = make()
        with self._lock:
            self._kept[key] = (value, self._nbytes(value) if size is None else size)
            self._kept.move_to_end(key)
            self._make_room(0, keep_last=True)
        return value

    def _make_room(self, incoming: int, keep_last: bool = False) -> None:
        """Drop the least recently used until ``incoming`` more bytes fit (the lock held)."""
        floor = 1 if keep_last else 0
        while len(self._kept) > floor and (
            sum(size for _, size in self._kept.values()) + incoming > self.keep_bytes
        ):
            self._kept.popitem(last=False)


def keep_parsed(
    keep_bytes: int, nbytes: Callable[[Any], int]
) -> Callable[[Callable[..., T]], Callable[..., T]]:
    """Decorator: a parse function's results kept by its (hashable) arguments in a
    :class:`Kept` of ``keep_bytes`` (the arguments must name the file's content)."""

    def decorate(parse: Callable[..., T]) -> Callable[..., T]:
        kept: Kept[T] = Kept(keep_bytes, nbytes)

        @functools.wraps(parse)
        def cached(*key: Hashable) -> T:
            return kept.get(key, lambda: parse(*key))

        return cached

    return decorate
