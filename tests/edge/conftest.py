"""Fixtures of the edge-budget tests."""

from __future__ import annotations

import pytest

from sdt_framework import build_registry


@pytest.fixture(scope="session")
def registry():
    """The installed registry (built-in plugins)."""
    return build_registry()


@pytest.fixture(scope="session")
def paper8(registry):
    """The built-in paper8 feature set."""
    return registry.feature_set("paper8")
