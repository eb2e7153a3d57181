"""Each figure function on hand-made data: a readable PNG, and the numbers it is meant to show."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from sdt_framework.report.figures_features import lowest_severity, plot_tsne
from sdt_framework.report.figures_scores import (
    best_class_f1,
    plot_confusions,
    plot_radar,
    worst_cells,
)
from sdt_framework.report.figures_signal import plot_noise, plot_sdt_overlay
from sdt_framework.report.signals import SensorTrace, noise_checks
from sdt_framework.report.style import REFERENCE_COLOR, save_figure, sensor_colors

from .conftest import assert_real_png

SENSORS = ["ref", "mems-a", "mems-b"]
COLORS = sensor_colors(SENSORS, "ref")
KEYS = ["machine", "scenario", "sensor", "classifier", "repeat"]


def test_palette_is_stable_and_reference_is_grey():
    assert COLORS["ref"] == REFERENCE_COLOR
    assert len(set(COLORS.values())) == 3
    # the same names give the same colours whatever the reference's position
    assert sensor_colors(["mems-a", "ref", "mems-b"], "ref") == COLORS


def _per_class(rng: np.random.Generator) -> pd.DataFrame:
    rows = []
    classes = {"M1": ["healthy", "fault a", "fault b", "fault c"], "M2": ["healthy", "x", "y"]}
    for machine, names in classes.items():
        for scenario in ("forward", "backward", "interpolation"):
            for sensor in SENSORS:
                for clf in ("lr", "knn"):
                    for repeat in (0, 1):
                        for name in names:
                            f1 = rng.uniform(0.2, 1.0)
                            rows.append((machine, scenario, sensor, clf, repeat, name, f1))
    return pd.DataFrame(rows, columns=[*KEYS, "class", "f1"])


def test_best_class_f1_averages_repeats_then_takes_the_best_classifier():
    rows = [
        ("M", "forward", "s", "lr", 0, "a", 1.0),
        ("M", "forward", "s", "lr", 1, "a", 0.0),  # lr mean 0.5
        ("M", "forward", "s", "knn", 0, "a", 0.7),
        ("M", "forward", "s", "knn", 1, "a", 0.5),  # knn mean 0.6 -> best
    ]
    best = best_class_f1(pd.DataFrame(rows, columns=[*KEYS, "class", "f1"]))
    assert best["f1"].tolist() == pytest.approx([0.6])


def test_radar_png(tmp_path):
    fig = plot_radar(_per_class(np.random.default_rng(0)), SENSORS, COLORS)
    # M2 has 3 classes, M1 4: every (machine, scenario) chart is drawn
    assert sum(ax.name == "polar" for ax in fig.axes) == 6
    assert_real_png(save_figure(fig, tmp_path, "radar.png"))


def test_worst_cells_skip_the_reference():
    results = pd.DataFrame(
        [
            ("M", "forward", "ref", "lr", 0.1, "ok"),
            ("M", "forward", "mems-a", "lr", 0.4, "ok"),
            ("M", "backward", "mems-a", "knn", 0.3, "ok"),
            ("M", "backward", "mems-b", "knn", 0.05, "error"),  # failed runs do not count
        ],
        columns=["machine", "scenario", "sensor", "classifier", "macro_f1", "status"],
    )
    cells = worst_cells(results, "ref")
    assert cells[["scenario", "sensor", "classifier"]].values.tolist() == [
        ["backward", "mems-a", "knn"]
    ]


def test_confusion_rows_are_normalised(tmp_path):
    counts = {("a", "a"): 8, ("a", "b"): 2, ("b", "a"): 0, ("b", "b"): 5}
    rows = [
        ("M", "backward", "mems-a", "lr", r, t, p, n)
        for r in (0, 1)
        for (t, p), n in counts.items()
    ]
    confusion = pd.DataFrame(rows, columns=[*KEYS, "true", "predicted", "count"])
    cells = pd.DataFrame(
        [("M", "backward", "mems-a", "lr", 0.7)],
        columns=["machine", "scenario", "sensor", "classifier", "macro_f1"],
    )
    fig = plot_confusions(confusion, cells)
    shares = fig.axes[0].images[0].get_array()
    assert np.allclose(shares, [[0.8, 0.2], [0.0, 1.0]])
    assert "0.80" in [t.get_text() for t in fig.axes[0].texts]
    assert_real_png(save_figure(fig, tmp_path, "confusion.png"))


def test_tsne_one_panel_per_sensor_with_lowest_severity(tmp_path):
    rng = np.random.default_rng(1)
    rows = []
    for sensor in SENSORS[:2]:
        for condition, severity in (("healthy", None), ("fault", 1), ("fault", 2), ("other", 2)):
            centre = rng.normal(size=8) * 4
            for w in range(40):
                rows.append(
                    {
                        "machine": "M",
                        "run": f"{condition} {severity}",
                        "condition": condition,
                        "severity": severity,
                        "sensor": sensor,
                        "window": w,
                        **{f"f{i}": v for i, v in enumerate(centre + rng.normal(size=8))},
                    }
                )
    features = pd.DataFrame(rows)
    chosen = lowest_severity(features)
    # fault level 2 is not the lowest; "other" has only level 2, so it is its lowest
    assert set(zip(chosen["condition"], chosen["severity"].fillna(0), strict=True)) == {
        ("healthy", 0),
        ("fault", 1),
        ("other", 2),
    }
    fig = plot_tsne(chosen, SENSORS, max_points=100)
    assert [ax.get_title() for ax in fig.axes] == ["ref (100 windows)", "mems-a (100 windows)"]
    assert_real_png(save_figure(fig, tmp_path, "tsne.png"))


def test_overlay_marks_full_scale_of_clipped_profiles_only(tmp_path):
    fs = 20000.0
    t = np.arange(int(fs * 0.5)) / fs
    x = np.sin(2 * np.pi * 150 * t) * np.exp(-((t - 0.25) ** 2) / 1e-3) * 30
    small = t[::5]
    traces = [
        SensorTrace("ref", x, fs, 80.0, 1e-5),
        SensorTrace("mems-a", np.clip(x[::5], -16, 16), fs / 5, 16.0, 0.004),
        SensorTrace("mems-b", 0.9 * x[::5] * (small < 1), fs / 5, 40.0, 1e-4),
    ]
    assert [tr.clipped for tr in traces] == [False, True, False]
    fig = plot_sdt_overlay(traces, COLORS)
    ax_t = fig.axes[0]
    levels = sorted(line.get_ydata()[0] for line in ax_t.lines if line.get_linestyle() == ":")
    assert levels == [-16.0, 16.0]
    labels = ax_t.get_legend_handles_labels()[1]
    assert labels == ["ref", "mems-a (clipped)", "mems-b"]
    assert ax_t.get_xlim()[1] <= 85  # about 80 ms shown, not the whole 500 ms
    assert fig.axes[1].get_xscale() == "log" and fig.axes[1].get_yscale() == "log"
    assert_real_png(save_figure(fig, tmp_path, "overlay.png"))


def test_noise_figure_from_noise_check(registry, tmp_path):
    noise = noise_checks([registry.sensor(name) for name in ("adxl345", "adxl357")], seed=0)
    fig = plot_noise(noise, sensor_colors(["adxl345", "adxl357"], None))
    labels = fig.axes[1].get_legend_handles_labels()[1]
    assert any(label.startswith("adxl345: NSD 2") for label in labels)  # ~290 µg/√Hz
    # the ADXL357's NSD is read under its 1000 Hz digital low-pass: near its configured 90
    assert any(label.startswith("adxl357: NSD 8") and "10–1000 Hz" in label for label in labels)
    assert_real_png(save_figure(fig, tmp_path, "noise.png"))
