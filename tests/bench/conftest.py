"""Small, fast benchmark configurations on the synthetic pump."""

from __future__ import annotations

from typing import Any

import pytest

from sdt_framework.bench.config import BenchmarkConfig

#: Motor-2 only (15 runs), 1.5 s acquisitions (2 windows per channel), 2 channels.
SMALL: dict[str, Any] = {
    "dataset_options": {"duration": 1.5},
    "machines": ["Motor-2"],
    "channels": ["ch1", "ch4"],
    "sensors": ["wilcoxon-786b10", "adxl345"],
    "classifiers": ["lr", "knn"],
    "repeats": 2,
    "jobs": 1,
    "report": False,
}


@pytest.fixture
def small_config(tmp_path):
    """Factory for a small config with its own feature cache."""

    def make(**changes: Any) -> BenchmarkConfig:
        return BenchmarkConfig(**{**SMALL, "cache_dir": str(tmp_path / "cache"), **changes})

    return make
