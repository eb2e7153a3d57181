"""Fixtures of the edge-budget tests."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def paper8(registry):
    """The built-in paper8 feature set."""
    return registry.feature_set("paper8")
