"""Fixtures of the synthetic pump's tests."""

from __future__ import annotations

import dataclasses

import pytest
from sdt_plugins.datasets.synthetic_pump import model


@pytest.fixture
def no_scatter(monkeypatch: pytest.MonkeyPatch) -> None:
    """The physical model alone: no installation scatter, drift or source scatter."""
    for name in ("FLOW_POINT_SD", "HF_MOUNT_SD", "ACQUISITION_DRIFT", "AMPLITUDE_SCATTER"):
        monkeypatch.setattr(model, name, 0.0)
    monkeypatch.setattr(model, "LEVEL_SCATTER", (0.0, 0.0))
    for ch, path in model.CHANNELS.items():
        monkeypatch.setitem(model.CHANNELS, ch, dataclasses.replace(path, install_sd=0.0))
