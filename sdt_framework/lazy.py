"""A package's public names, each loaded from its submodule on first use (PEP 562).

``sdt_framework.data`` and ``sdt_framework.chain`` export names whose modules
import scipy.signal (about 0.5 s); a plugin or command that needs only a light
name (``SameRate``, ``csv_signal``) should not pay for the rest at every ``sdt``
start. A package keeps its ``name -> submodule`` table and takes its module
``__getattr__`` and ``__dir__`` from :func:`lazy_exports`.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable, Mapping
from typing import Any

__all__ = ["lazy_exports"]


def lazy_exports(
    package: str, where: Mapping[str, str], namespace: Mapping[str, Any]
) -> tuple[Callable[[str], Any], Callable[[], list[str]]]:
    """(``__getattr__``, ``__dir__``) for ``package``: ``where`` maps each public name to
    the submodule (relative to ``package``) that defines it; ``namespace`` is the
    package's ``globals()``."""

    def attribute(name: str) -> Any:
        if name not in where:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        return getattr(importlib.import_module(f".{where[name]}", package), name)

    def names() -> list[str]:
        return sorted({*namespace, *where})

    return attribute, names
