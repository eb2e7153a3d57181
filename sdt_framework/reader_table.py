"""The table of registered signal readers, handed from the registry down to the data layer.

The data layer (:mod:`sdt_framework.data`) sits below the registry and never
imports it. :mod:`sdt_framework.registry` installs, when imported, a function
returning the default registry's readers; a caller holding its own registry
passes ``readers=`` instead. Kept in a module of its own, free of heavy
imports, so that installing it costs nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from .errors import InternalError

__all__ = ["install_reader_table", "reader_table"]

_table: Callable[[], Sequence[Any]] | None = None


def install_reader_table(table: Callable[[], Sequence[Any]]) -> None:
    """Install the function giving the registered readers (``ReaderSpec``)."""
    global _table
    _table = table


def reader_table() -> list[Any]:
    """The installed readers, sorted by name."""
    if _table is None:
        raise InternalError(
            "no signal readers installed: import sdt_framework.registry, or pass readers="
        )
    return list(_table())
