"""100 000-character class and sensor names are cut in the report's figures (issue 29).

On main a benchmark whose manifest named its conditions with 100 000
characters spent about 650 of 690 s in matplotlib drawing them whole in tick
labels and legends. The figures now draw at most 40 characters of a label,
its first and last 19 around an ellipsis; the tables and files keep it whole.
"""

from __future__ import annotations

import pandas as pd

from sdt_framework.report.figures_scores import plot_confusions, plot_radar
from sdt_framework.report.style import sensor_colors

LONG = 100_000
CLASSES = ["healthy" + "h" * LONG, "fault a" + "a" * LONG + "end", "fault b" + "b" * LONG]
SENSORS = ["ref", "mems" + "m" * LONG]


def _drawn(fig) -> list[str]:
    """Every tick label and legend entry of ``fig``, newlines removed."""
    texts = [t.get_text() for ax in fig.axes for t in ax.get_xticklabels() + ax.get_yticklabels()]
    texts += [t.get_text() for legend in fig.legends for t in legend.get_texts()]
    return [t.replace("\n", " ") for t in texts if t]


def test_radar_and_confusion_draw_long_names_cut_to_40_characters():
    rows = [
        ("M", scenario, sensor, "lr", 0, name, 0.5)
        for scenario in ("forward", "backward", "interpolation")
        for sensor in SENSORS
        for name in CLASSES
    ]
    per_class = pd.DataFrame(
        rows, columns=["machine", "scenario", "sensor", "classifier", "repeat", "class", "f1"]
    )
    radar = plot_radar(per_class, SENSORS, sensor_colors(SENSORS, "ref"))
    n = len(CLASSES)
    confusion = pd.DataFrame(
        [("M", "forward", SENSORS[1], "lr", 0, t, p, 1) for t in CLASSES for p in CLASSES],
        columns=["machine", "scenario", "sensor", "classifier", "repeat", "true", "predicted",
                 "count"],
    )  # fmt: skip
    cells = pd.DataFrame([{"machine": "M", "scenario": "forward", "sensor": SENSORS[1],
                           "classifier": "lr", "macro_f1": 1 / n}])  # fmt: skip
    matrix = plot_confusions(confusion, cells)
    for fig in (radar, matrix):
        drawn = _drawn(fig)
        class_labels = [t for t in drawn if t.startswith(("healthy", "fault"))]
        assert class_labels, drawn[:5]
        assert max(len(t) for t in drawn) <= 40
        # both ends of a name stay readable: "fault a" … "end"
        assert any(t.startswith("fault a") and t.endswith("aend") for t in class_labels)
    assert any(t.startswith("mems") and "…" in t for t in _drawn(radar))
