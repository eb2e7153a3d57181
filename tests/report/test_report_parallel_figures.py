"""Figures drawn side by side in worker processes give the report drawn in one process."""

from __future__ import annotations

from sdt_framework.report import figures
from sdt_framework.report.build import CAPTIONS
from sdt_framework.report.load import load_results
from sdt_framework.report.style import sensor_colors

from .conftest import assert_real_png


def _draw(results_dir, registry, out, processes, monkeypatch):
    monkeypatch.setattr(figures, "_processes", lambda count: processes)
    folder = load_results(results_dir)
    colors = sensor_colors(folder.sensors, folder.reference)
    return figures.draw_figures(folder, registry, colors, out, CAPTIONS)


def test_parallel_figures_equal_the_serial_ones(results_dir, registry, tmp_path, monkeypatch):
    (results_dir / "features.parquet").unlink()  # Fig. 3 cannot be drawn: its note stays
    serial = _draw(results_dir, registry, tmp_path / "one", 1, monkeypatch)
    parallel = _draw(results_dir, registry, tmp_path / "two", 2, monkeypatch)
    strip = [repr(b).replace(str(tmp_path / "two"), str(tmp_path / "one")) for b in parallel]
    assert strip == [repr(b) for b in serial]  # same headings, captions, notes, in order
    drawn = sorted(p.name for p in (tmp_path / "two").glob("*.png"))
    assert drawn == sorted(f for k, (f, _) in figures.FIGURES.items() if k != "fig3")
    for name in drawn:
        assert_real_png(tmp_path / "two" / name)
    assert "Not drawn: features.parquet is missing or empty." in str(parallel)
