"""Whole-file parses kept for the next call, bounded by the memory they hold.

A text format (LVM, UFF) is parsed in full to scan, probe or read any one of its
signals, and a benchmark probes every file of a campaign before it reads the
first: a cache of the last file or two parsed every file of a campaign two or
three times. :func:`keep_parsed` keeps the most recently used parses while their
arrays hold at most ``keep_bytes``, and always the last one, however large (so a
file bigger than the bound is still parsed once for its scan, probe and read, as
before).
"""

from __future__ import annotations

import functools
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import Any, TypeVar

__all__ = ["keep_parsed"]

T = TypeVar("T")


def keep_parsed(
    keep_bytes: int, nbytes: Callable[[Any], int]
) -> Callable[[Callable[..., T]], Callable[..., T]]:
    """Decorator: a parse function's results by its (hashable) arguments, the most recently
    used first, while ``nbytes`` of them sums to ``keep_bytes`` at most (the last always).

    The caller's arguments must name the file's content (a digest, or its size and time):
    a changed file must be another key. An error is not kept; the next call parses again.
    """

    def decorate(parse: Callable[..., T]) -> Callable[..., T]:
        kept: OrderedDict[Hashable, tuple[T, int]] = OrderedDict()
        lock = threading.Lock()

        @functools.wraps(parse)
        def cached(*key: Hashable) -> T:
            with lock:
                if key in kept:
                    kept.move_to_end(key)
                    return kept[key][0]
            value = parse(*key)
            with lock:
                kept[key] = (value, nbytes(value))
                while len(kept) > 1 and sum(size for _, size in kept.values()) > keep_bytes:
                    kept.popitem(last=False)
            return value

        return cached

    return decorate
