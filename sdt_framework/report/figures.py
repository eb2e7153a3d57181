"""Draw every report figure from a results folder; a figure that cannot be drawn says why.

Each figure is attempted on its own: missing inputs (no features table, no
configuration to re-open the dataset, ...) give a short "not drawn" note, and
an unexpected failure of one figure is reported in the document instead of
stopping the other figures or the tables. The figures are drawn in parallel
worker processes (the serial tail of a benchmark on a many-core machine).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from joblib import Parallel, delayed
from matplotlib.figure import Figure as MplFigure

from ..bench.results import SCENARIO_TITLES
from ..errors import SDTError
from ..specs import SensorSpec
from .document import Block, Figure, Heading, Paragraph, literal
from .figures_features import lowest_severity, plot_tsne
from .figures_scores import plot_confusions, plot_radar, worst_cells
from .figures_signal import plot_noise, plot_sdt_overlay
from .load import ResultsFolder
from .pick import pick_recording
from .signals import degrade_all, noise_checks, open_config_dataset
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


Draw = Callable[..., tuple[MplFigure, str]]


def _fig2(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[Draw, tuple]:
    if folder.config is None:
        raise MissingInputError("config.toml is missing or invalid: cannot re-open the dataset")
    recordings = open_config_dataset(folder.config, registry)
    choice = pick_recording(recordings, folder.features, folder.reference)
    return _draw_fig2, (choice, _specs(folder, registry), folder.config.seed, colors)


def _draw_fig2(
    choice: Any, specs: list[SensorSpec], seed: int, colors: dict[str, str]
) -> tuple[MplFigure, str]:
    recording = choice.recording
    _, traces = degrade_all(recording, specs, seed)
    name = f"{recording.machine} / {recording.run} / {recording.channel}"
    fig = plot_sdt_overlay(traces, colors, title=f"{name}, first acquisition")
    return fig, f"{literal(name)}, acquisition 0, seed {seed}. Channel {literal(choice.reason)}."


def _fig3(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[Draw, tuple]:
    if folder.features is None or folder.features.empty:
        raise MissingInputError("features.parquet is missing or empty")
    machine = sorted(folder.features["machine"].unique())[0]
    rows = lowest_severity(folder.features, machine)
    seed = folder.config.seed if folder.config is not None else 0
    title = f"{machine}: healthy + lowest severity level of each fault"
    return _draw_fig3, (rows, folder.sensors, seed, title)


def _draw_fig3(rows: Any, sensors: list[str], seed: int, title: str) -> tuple[MplFigure, str]:
    return plot_tsne(rows, sensors, seed=seed, title=title), literal(title) + "."


def _fig4(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[Draw, tuple]:
    specs = [s for s in _specs(folder, registry) if s.inject_noise]
    if not specs:
        raise MissingInputError("no sensor of this benchmark injects noise")
    return _draw_fig4, (specs, folder.config.seed if folder.config else 0, colors)


def _draw_fig4(specs: list[SensorSpec], seed: int, colors: dict[str, str]) -> tuple[MplFigure, str]:
    noise = noise_checks(specs, seed)
    stats = "; ".join(literal(n.caption()) for n in noise)
    return plot_noise(noise, colors), f"8 windows of 2048 samples. {stats}."


def _fig6(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[Draw, tuple]:
    if folder.per_class is None or folder.per_class.empty:
        raise MissingInputError("per_class.parquet is missing or empty")
    ok = folder.ok[["machine", "scenario", "sensor", "classifier", "repeat"]]
    per_class = folder.per_class.merge(ok, how="inner")
    if per_class.empty:
        raise MissingInputError("no successful run has per-class scores")
    return _draw_fig6, (per_class, folder.sensors, colors)


def _draw_fig6(per_class: Any, sensors: list[str], colors: dict[str, str]) -> tuple[MplFigure, str]:
    return plot_radar(per_class, sensors, colors), "One chart per machine and scenario."


def _fig7(folder: ResultsFolder, registry: Any, colors: dict[str, str]) -> tuple[Draw, tuple]:
    if folder.confusion is None or folder.confusion.empty:
        raise MissingInputError("confusion.parquet is missing or empty")
    cells = worst_cells(folder.results, folder.reference)
    if cells.empty:
        raise MissingInputError("no successful run")
    text = "; ".join(
        literal(
            f"{c.machine}: {SCENARIO_TITLES.get(c.scenario, c.scenario)}, {c.sensor}, "
            f"{str(c.classifier).upper()} (macro F1 {c.macro_f1:.3f})"
        )
        for c in cells.itertuples()
    )
    return _draw_fig7, (folder.confusion, cells, text)


def _draw_fig7(confusion: Any, cells: Any, text: str) -> tuple[MplFigure, str]:
    return plot_confusions(confusion, cells), f"Cells: {text}."


#: per figure: what it needs, gathered in this process (the registry stays here)
_MAKERS: dict[str, Callable[[ResultsFolder, Any, dict[str, str]], tuple[Draw, tuple]]] = {
    "fig2": _fig2,
    "fig3": _fig3,
    "fig4": _fig4,
    "fig6": _fig6,
    "fig7": _fig7,
}


def _render(draw: Draw, args: tuple, folder: Path, name: str) -> tuple[str, str]:
    """Draw and save one figure (in a worker process): ("ok", caption detail) or
    ("failed", why); an exception never stops the other figures."""
    try:
        fig, detail = draw(*args)
        save_figure(fig, folder, name)
        return "ok", detail
    except Exception as exc:  # one broken figure must not lose the rest of the report
        return "failed", f"{type(exc).__name__}: {exc}".splitlines()[0][:300]


#: fewer cores than this draw in this process: on 2 cores shared with other work, starting
#: the worker processes and their imports cost more than they saved (report 47.8 s side by
#: side vs 28.9 s one after another, benchmarks/bench_scale.py's folder, load average 27)
PARALLEL_FROM_CORES = 4


def _processes(count: int) -> int:
    """Processes to draw ``count`` figures with (1: in this process)."""
    cores = os.cpu_count() or 1
    return 1 if cores < PARALLEL_FROM_CORES else max(1, min(count, cores))


def draw_figures(
    folder: ResultsFolder,
    registry: Any,
    colors: dict[str, str],
    out_dir: Path,
    captions: dict[str, str],
) -> list[Block]:
    """Draw each figure into ``out_dir`` (PNG) and return the report blocks for them.

    ``captions`` gives, per figure key, the fixed explanation of what it shows.
    Each figure's inputs are gathered here; on a machine with at least
    :data:`PARALLEL_FROM_CORES` cores the figures are drawn side by side in
    worker processes (one per figure, at most one per core), so the report
    waits for the slowest figure (the t-SNE) rather than for all of them.
    """
    blocks: dict[str, list[Block]] = {}
    todo: dict[str, tuple[Draw, tuple]] = {}
    for key, (_, title) in FIGURES.items():
        blocks[key] = [Heading(title, 3)]
        try:
            todo[key] = _MAKERS[key](folder, registry, colors)
        except MissingInputError as exc:
            blocks[key].append(Paragraph(f"Not drawn: {literal(exc)}."))
        except Exception as exc:  # one broken figure must not lose the rest of the report
            message = f"{type(exc).__name__}: {exc}".splitlines()[0][:300]
            blocks[key].append(Paragraph(f"Not drawn: the figure failed ({literal(message)})."))
    jobs = [
        delayed(_render)(draw, args, out_dir, FIGURES[key][0]) for key, (draw, args) in todo.items()
    ]
    n = _processes(len(jobs))
    drawn = Parallel(n_jobs=n, backend="loky")(jobs) if n > 1 else [j[0](*j[1]) for j in jobs]
    for key, (status, detail) in zip(todo, drawn, strict=True):
        title = FIGURES[key][1]
        if status == "ok":
            text = f"{captions.get(key, '')} {detail}".strip()
            blocks[key].append(Figure(out_dir / FIGURES[key][0], text, title))
        elif detail.startswith("MissingInputError: "):
            blocks[key].append(Paragraph(f"Not drawn: {literal(detail.split(': ', 1)[1])}."))
        else:
            blocks[key].append(Paragraph(f"Not drawn: the figure failed ({literal(detail)})."))
    return [block for key in FIGURES for block in blocks[key]]
