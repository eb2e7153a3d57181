"""The installed registry, built once per process for the transformers that look up names.

Cross-validation fits a pipeline many times; scanning the installed plugins on
every ``fit`` would cost more than the fit. Pass a spec object instead of a
name to use a sensor or feature set from another registry.
"""

from __future__ import annotations

from functools import cache

from sdt_framework.registry import Registry, build_registry

__all__ = ["installed_registry"]


@cache
def installed_registry() -> Registry:
    """``build_registry()``, once."""
    return build_registry()
