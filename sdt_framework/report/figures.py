"""Draw every report figure from a results folder; a figure that cannot be drawn says why.

Each figure is attempted on its own: missing inputs (no features table, no
configuration to re-open the dataset, ...) give a short "not drawn" note, and
an unexpected failure of one figure is reported in the document instead of
stopping the other figures or the tables.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

from matplotlib.figure import Figure as MplFigure

from ..bench.results import SCENARIO_TITLES
from ..errors import SDTError
from ..specs import SensorSpec
from .document import Block, Figure, Heading, Paragraph
from .figures_features import lowest_severity, plot_tsne
from .figures_scores import plot_confusions, plot_radar, worst_cells
from .figures_signal import plot_noise, plot_sdt_overlay
from .load import ResultsFolder
from .signals import degrade_all, noise_checks, open_config_dataset, pick_recording
from .style import save_figure

__all__ = ["FIGURES", "draw_figures"]

#: file name and title of each figure, in report order
FIGURES = {
    "fig2": ("fig2_sdt_signal.png", "Fig. 2 — the SDT on one recording"),
    "fig3": ("fig3_tsne.png", "Fig. 3 — feature space (t-SNE)"),
    "fig4": ("fig4_noise.png", "Fig. 4 — zero-motion noise of the MEMS profiles"),
    "fig6": ("fig6_radar.png", "Fig. 6 — best per-class F1 (radar)"),
    "fig7": ("fig7_confusion.png", "Fig. 7 — confusion matrices of the worst MEMS cells"),
}


class MissingInputError(Exception):
    """A figure's inputs are absent; the message says which."""


def _specs(folder: ResultsFolder, registry: Any) -> list[SensorSpec]:
    specs = []
    for name in folder.sensors:
        try:
            specs.append(registry.sensor(name))
        except SDTError:  # a sensor of an uninstalled plugin is left out, not fatal
            continue
    if not specs:
        raise MissingInputError("none of the results' sensors is registered here")
    return specs


def _fig2(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[MplFigure, str]:
    if folder.config is None:
        raise MissingInputError("config.toml is missing or invalid: cannot re-open the dataset")
    recording = pick_recording(open_config_dataset(folder.config, registry))
    specs = _specs(folder, registry)
    _, traces = degrade_all(recording, specs, folder.config.seed)
    name = f"{recording.machine} / {recording.run} / {recording.channel}"
    fig = plot_sdt_overlay(traces, colors, title=f"{name}, first acquisition")
    return fig, f"{name}, acquisition 0, seed {folder.config.seed}."


def _fig3(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[MplFigure, str]:
    if folder.features is None or folder.features.empty:
        raise MissingInputError("features.parquet is missing or empty")
    machine = sorted(folder.features["machine"].unique())[0]
    rows = lowest_severity(folder.features, machine)
    seed = folder.config.seed if folder.config is not None else 0
    title = f"{machine}: healthy + lowest severity level of each fault"
    return plot_tsne(rows, folder.sensors, seed=seed, title=title), title + "."


def _fig4(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[MplFigure, str]:
    checks = noise_checks(_specs(folder, registry), folder.config.seed if folder.config else 0)
    if not checks:
        raise MissingInputError("no sensor of this benchmark injects noise")
    stats = ", ".join(
        f"{c.sensor}: RMS {c.sdt.rms_mg.mean():.2f} mg, NSD {c.sdt.nsd_ug_rthz.mean():.1f} µg/√Hz"
        for c in checks
    )
    return plot_noise(checks, colors), f"8 windows of 2048 samples. {stats}."


def _fig6(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[MplFigure, str]:
    if folder.per_class is None or folder.per_class.empty:
        raise MissingInputError("per_class.parquet is missing or empty")
    ok = folder.ok[["machine", "scenario", "sensor", "classifier", "repeat"]]
    per_class = folder.per_class.merge(ok, how="inner")
    if per_class.empty:
        raise MissingInputError("no successful run has per-class scores")
    return plot_radar(per_class, folder.sensors, colors), "One chart per machine and scenario."


def _fig7(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[MplFigure, str]:
    if folder.confusion is None or folder.confusion.empty:
        raise MissingInputError("confusion.parquet is missing or empty")
    cells = worst_cells(folder.results, folder.reference)
    if cells.empty:
        raise MissingInputError("no successful run")
    text = "; ".join(
        f"{c.machine}: {SCENARIO_TITLES.get(c.scenario, c.scenario)}, {c.sensor}, "
        f"{c.classifier.upper()} (macro F1 {c.macro_f1:.3f})"
        for c in cells.itertuples()
    )
    return plot_confusions(folder.confusion, cells), f"Cells: {text}."


_MAKERS: dict[str, Callable[[ResultsFolder, Any, dict[str, str]], tuple[MplFigure, str]]] = {
    "fig2": _fig2,
    "fig3": _fig3,
    "fig4": _fig4,
    "fig6": _fig6,
    "fig7": _fig7,
}


def draw_figures(
    folder: ResultsFolder,
    registry: Any,
    colors: dict[str, str],
    out_dir: Path,
    captions: dict[str, str],
) -> list[Block]:
    """Draw each figure into ``out_dir`` (PNG) and return the report blocks for them.

    ``captions`` gives, per figure key, the fixed explanation of what it shows.
    """
    blocks: list[Block] = []
    for key, (filename, title) in FIGURES.items():
        blocks.append(Heading(title, 3))
        try:
            fig, detail = _MAKERS[key](folder, registry, colors)
            path = save_figure(fig, out_dir / filename)
            blocks.append(Figure(path, f"{captions.get(key, '')} {detail}".strip(), title))
        except MissingInputError as exc:
            blocks.append(Paragraph(f"Not drawn: {exc}."))
        except Exception as exc:  # one broken figure must not lose the rest of the report
            message = f"{type(exc).__name__}: {exc}".splitlines()[0][:300]
            blocks.append(Paragraph(f"Not drawn: the figure failed ({message})."))
    return blocks
