"""The spectra the field reads, per machine and sensor: envelope, velocity, spectra by level.

Recordings are re-opened from the configuration and passed through every
sensor's chain as for Fig. 2 (:mod:`.signals`), first acquisition, the
benchmark's seed. Each caption states the scaling, window, resolution
bandwidth and unit of every spectrum drawn (:class:`~sdt_framework.severity.Spectrum`).

- Envelope spectrum of each bearing-fault run (:mod:`.figures_envelope`): the
  faults of each bearing of the machine's spec, the bearing's defect lines.
- Velocity spectrum 10-1000 Hz (mm/s r.m.s. per line) of the recording the
  reference grades worst (largest mean V_RMS), each sensor's band cut to what
  its chain passes (:mod:`.passband`).
- Spectra by fault level (:mod:`.figures_levels`): ASD of the healthy runs and
  of each level of that recording's fault, on its channel, one panel per sensor.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pandas as pd

from ..chain import passband
from ..errors import SDTError
from ..labels import slug
from ..severity import velocity_spectrum
from .document import Block, Figure, Heading, Paragraph, literal
from .figures_envelope import envelope_blocks
from .figures_levels import MAX_TESTS, Level, levels_figure
from .load import ResultsFolder
from .machines import folder_machines
from .signals import SensorTrace, degrade_all
from .style import figure_label, new_figure, save_figure

__all__ = ["VELOCITY_BAND_HZ", "spectral_blocks"]

VELOCITY_BAND_HZ = (10.0, 1000.0)


def _velocity_figure(traces: list[SensorTrace], specs: dict, fs: float, colors, title: str):
    """Velocity spectra, each over 10-1000 Hz cut to what that sensor's chain passes."""
    fig = new_figure(11, 3.6)
    ax = fig.subplots()
    notes = []
    for trace in traces:
        limit = passband(specs[trace.sensor], fs)
        band = limit.clip(VELOCITY_BAND_HZ)
        if band is None:
            notes.append(f"{trace.sensor}: not drawn, {limit.note(VELOCITY_BAND_HZ)}")
            continue
        spec = velocity_spectrum(trace.signal, trace.fs, band)
        overall = spec.overall  # the band's V_RMS: lines' power over the window's ENBW
        cut = f", {band[0]:g}-{band[1]:.0f} Hz" if band != VELOCITY_BAND_HZ else ""
        ax.plot(
            spec.freq,
            spec.values,
            lw=0.8,
            color=colors.get(trace.sensor),
            label=f"{figure_label(trace.sensor)} ({overall:.2f} mm/s overall{cut})",
        )
        clipped = limit.note(VELOCITY_BAND_HZ)
        notes.append(f"{trace.sensor}: {spec.caption()}" + (f"; {clipped}" if clipped else ""))
    ax.set_yscale("log")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("velocity (mm/s r.m.s.)")
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=10)
    return fig, notes


def _worst(features: pd.DataFrame, reference: str, machine: str) -> pd.Series:
    rows = features[(features["sensor"] == reference) & (features["machine"] == machine)]
    means = rows.groupby("recording_id")["V_RMS"].mean()
    return rows[rows["recording_id"] == means.idxmax()].iloc[0]


def _levels(mine: list, rec: Any, specs: list, seed: int) -> list[Level]:
    """Healthy, then each level of ``rec``'s fault on its channel: at most MAX_TESTS tests each."""
    same = [r for r in mine if r.channel == rec.channel]
    groups: dict[Any, list] = {None: [r for r in same if r.severity is None]}
    for r in sorted(same, key=lambda r: (r.severity or 0, r.run)):
        if r.condition == rec.condition and r.severity is not None:
            groups.setdefault(r.severity, []).append(r)
    return [
        Level(
            "healthy" if level is None else f"level {level}",
            [degrade_all(r, specs, seed)[1] for r in runs[:MAX_TESTS]],
            len(runs),
        )
        for level, runs in groups.items()
        if runs
    ]


def _velocity_blocks(mine: list, rec: Any, specs: list, seed: int, figures_dir, colors):
    """Velocity spectrum of ``rec`` and the spectra by level of its fault on its channel."""
    machine, fs = rec.machine, rec.sampling_rate_hz
    by_name = {s.name: s for s in specs}
    _, traces = degrade_all(rec, specs, seed)
    title = f"{machine} {rec.run} {rec.channel}: velocity spectrum 10-1000 Hz (worst-graded)"
    fig, notes = _velocity_figure(traces, by_name, fs, colors, title)
    path = save_figure(fig, figures_dir, f"{slug('velocity', machine)}.png")
    caption = f"{title}. " + "; ".join(notes) + "."
    blocks: list[Block] = [Figure(path, literal(caption), literal(title))]
    levels = _levels(mine, rec, specs, seed)
    title = f"{machine} {rec.channel}: ASD by fault level, healthy and {rec.condition} levels"
    passbands = {s.name: passband(s, fs) for s in specs}
    fig, notes = levels_figure(levels, colors, passbands, title)
    path = save_figure(fig, figures_dir, f"{slug('levels', machine)}.png")
    caption = (
        f"{title}: the spectra overlaid by fault level (not a waterfall over time or speed), "
        f"one colour per level, every test drawn (at most {MAX_TESTS} per level); shaded: "
        "above each chain's bandwidth. " + "; ".join(notes) + "."
    )
    blocks.append(Figure(path, literal(caption), literal(title)))
    return blocks


def spectral_blocks(
    folder: ResultsFolder, registry: Any, figures_dir: Path, colors: dict[str, str]
) -> list[Block]:
    """Envelope, velocity and by-level figures per machine; a note when they cannot be drawn."""
    blocks: list[Block] = [Heading("Spectra", 3)]
    if folder.config is None or folder.features is None:
        return [*blocks, Paragraph("Not drawn: config.toml or features.parquet is missing.")]
    machines = folder_machines(folder, registry)
    if machines.problem:
        return [*blocks, Paragraph(f"Not drawn: {literal(machines.problem)}")]
    try:
        specs = [registry.sensor(name) for name in folder.sensors]
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not drawn: {literal(exc)}")]
    recordings = {r.recording_id: r for r in machines.recordings}
    seed = folder.config.seed
    features = folder.features
    for machine in sorted(features["machine"].unique()):
        mine = [r for r in recordings.values() if r.machine == machine]
        spec = machines.specs.get(machine)
        blocks += envelope_blocks(mine, machine, spec, specs, seed, figures_dir)
        rec = recordings.get(_worst(features, folder.reference, machine)["recording_id"])
        if rec is not None:
            blocks += _velocity_blocks(mine, rec, specs, seed, figures_dir, colors)
    return blocks
