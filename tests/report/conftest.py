"""A small real results folder (built once per session) and PNG checks for the report tests."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
from matplotlib import image

from sdt_framework.bench import BenchmarkConfig, run_benchmark_folder

#: Motor-2 only, 1.5 s acquisitions, 2 channels, reference + one MEMS, 2 classifiers.
SMALL = {
    "dataset_options": {"duration": 1.5},
    "machines": ["Motor-2"],
    "channels": ["ch1", "ch4"],
    "sensors": ["wilcoxon-786b10", "adxl345"],
    "classifiers": ["lr", "knn"],
    "repeats": 2,
    "jobs": 1,
    "report": False,
}


@pytest.fixture(scope="session")
def results_master(tmp_path_factory, registry) -> Path:
    """A benchmark results folder, written once; tests copy it (see ``results_dir``)."""
    root = tmp_path_factory.mktemp("report-results")
    config = BenchmarkConfig(**{**SMALL, "cache_dir": str(root / "cache")})
    out = root / "results"
    run_benchmark_folder(config, registry, out)
    return out


@pytest.fixture
def results_dir(results_master, tmp_path) -> Path:
    """A private copy of the small results folder, free to damage."""
    target = tmp_path / "results"
    shutil.copytree(results_master, target, ignore=shutil.ignore_patterns("runs", "cache"))
    return target


@pytest.fixture(scope="session")
def full_report(results_master, registry, tmp_path_factory):
    """(folder, written) of the report of an intact copy of the small results folder."""
    from sdt_framework.report import write_report

    target = tmp_path_factory.mktemp("full") / "results"
    shutil.copytree(results_master, target, ignore=shutil.ignore_patterns("runs", "cache"))
    return target, write_report(target, registry=registry)


def assert_real_png(path: Path, min_bytes: int = 8000) -> None:
    """``path`` is a PNG a person could look at: decodes, big enough, many colours."""
    assert path.is_file(), path
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    assert path.stat().st_size > min_bytes, f"{path}: only {path.stat().st_size} bytes"
    pixels = image.imread(path)
    assert pixels.ndim == 3 and pixels.shape[0] > 300 and pixels.shape[1] > 400, pixels.shape
    rgb = (pixels[..., :3] * 255).astype(np.uint32).reshape(-1, 3)
    colours = np.unique(rgb[:, 0] << 16 | rgb[:, 1] << 8 | rgb[:, 2])
    assert len(colours) > 30, f"{path}: only {len(colours)} distinct colours"
    white = np.all(rgb > 250, axis=1).mean()
    assert 0.2 < white < 0.995, f"{path}: {white:.1%} white pixels"
