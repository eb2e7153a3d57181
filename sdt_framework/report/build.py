"""Assemble the report of a results folder and write report.md / report.html atomically."""

from __future__ import annotations

import os
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from ..errors import SDTError
from ..io import atomic_write_text
from .decision import decision_blocks
from .deployment import deployment_blocks
from .document import Block, Code, Heading, Items, Paragraph, Table, code, literal
from .edge import edge_blocks
from .exploration import exploration_blocks
from .figures import draw_figures
from .load import ResultsFolder, load_results
from .node_edge import node_blocks
from .render import render_html, render_markdown
from .severity import severity_blocks
from .speed import speed_blocks
from .style import sensor_colors
from .tables import allocation_table, delta_table, failed_table, table4_table
from .units import unit_blocks
from .verdict import missing_reference_note, verdict_blocks

__all__ = ["CAPTIONS", "FORMATS", "build_blocks", "write_report"]

FORMATS = ("md", "html")

#: what each figure shows (the fixed part of its caption)
CAPTIONS = {
    "fig2": "Paper Fig. 2: the recording (default: the highest cavitation-suction level, on "
    "the channel where it differs most from healthy) through every sensor's chain. (a) ~80 ms "
    "around the reference's largest peak; dotted lines mark ±G_max of clipped profiles. "
    "(b) Welch amplitude spectral density.",
    "fig3": "Paper Fig. 3: 2-D t-SNE of the standardised repetition-0 features, one panel per "
    "sensor, coloured by class; at most 1000 windows per sensor (fixed random state).",
    "fig4": "Paper Fig. 4: the chain of each noise-injecting profile on x_ref = 0 "
    "(as `sdt validate-noise`). (a) time trace; (b) ASD and mean NSD, each read over "
    "10–1500 Hz cut to the band that profile's chain passes (its lowest corner or Nyquist).",
    "fig6": "Paper Fig. 6: per class, the best F1 over classifiers (each classifier's F1 "
    "averaged over repetitions first), per sensor.",
    "fig7": "Paper Fig. 7: confusion matrices summed over repetitions and row-normalised, "
    "for each machine's worst non-reference cell (lowest mean macro F1).",
}


def _dataset(folder: ResultsFolder) -> str:
    summary, res = folder.summary or {}, folder.results
    if "dataset" in summary:
        return str(summary["dataset"])
    return str(res["dataset"].iloc[0]) if len(res) and "dataset" in res else "?"


def _overview(folder: ResultsFolder) -> list[Block]:
    res = folder.results
    blocks: list[Block] = [
        Heading(f"Benchmark report: {literal(folder.path.name)}", 1),
        Paragraph(
            f"Dataset **{literal(_dataset(folder))}**; "
            f"{len(res)} runs ({len(folder.ok)} ok, {len(folder.failed)} failed) over "
            f"{res['machine'].nunique()} machine(s), {res['scenario'].nunique()} scenario(s), "
            f"{len(folder.sensors)} sensor(s) ({', '.join(map(literal, folder.sensors))}), "
            f"{res['classifier'].nunique()} classifier(s). Reference sensor: "
            f"{code(folder.reference)}."
        ),
    ]
    if folder.problems:
        blocks += [
            Paragraph(
                "**Missing or unreadable inputs** (parts of the report that need "
                "them are left out):"
            ),
            Items(tuple(map(literal, folder.problems))),
        ]
    return blocks


def _provenance(folder: ResultsFolder) -> list[Block]:
    blocks: list[Block] = [Heading("Provenance", 2)]
    summary = folder.summary or {}
    if folder.allocation is not None and not folder.allocation.empty:
        blocks += [Heading("Train/test allocation", 3), allocation_table(folder.allocation)]
    if folder.skipped is not None and not folder.skipped.empty:
        rows = tuple(tuple(map(literal, r)) for r in folder.skipped.itertuples(index=False))
        blocks += [
            Heading("Skipped machine/scenario pairs", 3),
            Table(tuple(map(literal, folder.skipped.columns)), rows),
        ]
    if summary.get("dataset_skipped"):
        items = tuple(
            f"{literal(s.get('path'))}: {literal(s.get('reason'))}"
            for s in summary["dataset_skipped"]
        )
        blocks += [Heading("Dataset entries skipped", 3), Items(items)]
    blocks.append(Heading("Configuration (config.toml)", 3))
    blocks.append(
        Code(folder.config_text, "toml")
        if folder.config_text
        else Paragraph("config.toml is missing.")
    )
    if summary:
        seconds = summary.get("seconds", {})
        timing = tuple((literal(k), f"{float(v):.1f}") for k, v in seconds.items())
        total = ("total", f"{sum(seconds.values()):.1f}")
        blocks += [Heading("Timing", 3), Table(("stage", "seconds"), (*timing, total))]
        counts = [
            k
            for k in (
                "runs_computed",
                "runs_resumed",
                "feature_blocks_computed",
                "feature_blocks_cached",
            )
            if k in summary
        ]
        if counts:
            blocks.append(
                Items(tuple(f"{k.replace('_', ' ')}: {literal(summary[k])}" for k in counts))
            )
        software = summary.get("software", {})
        blocks += [
            Heading("Software", 3),
            Table(
                ("package", "version"), tuple((literal(k), literal(v)) for k, v in software.items())
            ),
        ]
    return blocks


def _saturation(folder: ResultsFolder) -> list[Block]:
    """A section naming the recordings a sensor saw mostly at its full scale, if any."""
    entries = (folder.summary or {}).get("saturation", {})
    rows = tuple(
        (
            literal(sensor),
            f"+-{entry['full_scale_g']:g} g",
            f"{entry['fraction']:.2%}",
            f"{entry['recordings_above_limit']} of {entry['recordings']}",
            ", ".join(
                f"{literal(w['recording_id'])} ({w['fraction']:.0%})" for w in entry["worst"]
            ),
        )
        for sensor, entry in entries.items()
        if entry.get("recordings_above_limit")
    )
    if not rows:
        return []
    limit = next(iter(entries.values()))["limit"]
    return [
        Heading("Saturation", 2),
        Paragraph(
            f"Samples at the sensor's full scale (clipped by the twin) in repetition 0. A "
            f"recording is listed when at least {limit:.0%} of its samples are: its windows "
            f"show the clipped signal, and its scores say what the part would have done there."
        ),
        Table(("sensor", "full scale", "all samples", "recordings above", "worst"), rows),
    ]


def build_blocks(folder: ResultsFolder, registry: Any, figures_dir: Path) -> list[Block]:
    """The whole report as blocks; draws the figures into ``figures_dir``."""
    colors = sensor_colors(folder.sensors, folder.reference)
    blocks = _overview(folder)
    blocks += decision_blocks(folder, registry)
    blocks += verdict_blocks(folder, colors, figures_dir)
    blocks += [
        Heading("Table 4: Macro F1 (mean ± SD)", 2),
        table4_table(folder.results, folder.sensors),
    ]
    delta = delta_table(folder.results, folder.sensors, folder.reference)
    blocks.append(Heading(f"Delta to the reference ({literal(folder.reference)})", 2))
    note = missing_reference_note(folder)
    if delta is None or note is not None:
        text = note or (
            f"Not shown: the reference sensor {literal(folder.reference)} has no successful run."
        )
        blocks.append(Paragraph(text))
    else:
        blocks.append(delta)
    blocks += speed_blocks(folder)
    if not folder.failed.empty:
        blocks += [Heading("Failed runs", 2), failed_table(folder.failed)]
    blocks += _saturation(folder)
    blocks += severity_blocks(folder, registry, figures_dir, colors)
    blocks += unit_blocks(folder)
    blocks += deployment_blocks(folder, registry)
    blocks += exploration_blocks(folder.path, figures_dir)
    blocks += edge_blocks(folder, registry)
    blocks += node_blocks(folder, registry)
    blocks.append(Heading("Figures", 2))
    blocks += draw_figures(folder, registry, colors, figures_dir, CAPTIONS)
    return blocks + _provenance(folder)


def write_report(
    results_dir: str | os.PathLike[str],
    formats: Sequence[str] = FORMATS,
    *,
    registry: Any = None,
    out_dir: str | os.PathLike[str] | None = None,
) -> dict[str, Path]:
    """Write the report of ``results_dir`` into that folder (or into ``out_dir``).

    Parameters
    ----------
    results_dir
        A folder written by ``sdt benchmark``; only the results table is required.
    formats
        Any of "md" (report.md, figures linked) and "html" (report.html, self-contained).
    registry
        Registry used to look up sensors and the dataset; default: the installed one.
    out_dir
        Folder for the report and its figures (default ``results_dir``), e.g.
        when ``results_dir`` is read-only; it is created if needed.

    Returns
    -------
    dict
        ``{format: path}`` of each file written; figures go to ``<out_dir>/figures``.

    Raises
    ------
    SDTError
        For an unknown format, a path that is not a folder, or no results table.
    """
    unknown = sorted(set(formats) - set(FORMATS))
    if unknown or not formats:
        raise SDTError(f"unknown report format(s) {unknown or formats}; choose from md, html")
    start = time.perf_counter()
    folder = load_results(results_dir)
    if registry is None:
        from ..registry import build_registry

        registry = build_registry()
    target = Path(out_dir) if out_dir is not None else folder.path
    target.mkdir(parents=True, exist_ok=True)
    blocks = build_blocks(folder, registry, target / "figures")
    took = time.perf_counter() - start
    blocks.append(Paragraph(f"Report drawn in {took:.1f} s by `sdt report`."))
    written: dict[str, Path] = {}
    if "md" in formats:
        written["md"] = target / "report.md"
        atomic_write_text(written["md"], render_markdown(blocks, target), root=target)
    if "html" in formats:
        written["html"] = target / "report.html"
        title = f"sdt-framework report: {literal(folder.path.name)}"
        atomic_write_text(written["html"], render_html(blocks, title), root=target)
    return written
