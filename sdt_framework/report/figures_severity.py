"""The spectra the field reads, per machine and sensor: envelope, velocity, severity waterfall.

Recordings are re-opened from the configuration and passed through every
sensor's chain as for Fig. 2 (:mod:`.signals`), first acquisition, the
benchmark's seed. Each caption states the scaling, window, resolution
bandwidth and unit of every spectrum drawn (:class:`~sdt_framework.severity.Spectrum`).

- Envelope spectrum of each bearing-fault run (highest level): band-pass
  under each chain's bandwidth (:func:`~sdt_framework.severity.envelope_band`),
  Hilbert envelope, with the bearing's BPFO/BPFI/BSF/FTF at the running speed
  read off the reference's spectrum.
- Velocity spectrum 10-1000 Hz (mm/s r.m.s. per line) of the recording the
  reference grades worst (largest mean V_RMS).
- Severity waterfall: ASD of the healthy run and of each level of that
  recording's fault, on its channel, one panel per sensor.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.figure import Figure as MplFigure

from ..data.synth_model import MACHINES
from ..errors import SDTError
from ..labels import slug
from ..severity import (
    BEARINGS,
    asd,
    chain_bandwidth,
    defect_frequencies,
    envelope_band,
    envelope_spectrum,
    running_speed,
    velocity_spectrum,
)
from .document import Block, Figure, Heading, Paragraph, literal
from .load import ResultsFolder
from .signals import SensorTrace, degrade_all, open_config_dataset
from .style import new_figure, save_figure

__all__ = ["BEARING_RUNS", "envelope_figure", "spectral_blocks"]

#: bearing-fault condition -> (bearing, channel nearest to it in the NLN-EMP layout)
BEARING_RUNS = {
    "bearing bpfo": ("6309", "ch2"),
    "bearing bpfi": ("6309", "ch2"),
    "bearing pump": ("6308", "ch4"),
}
_LINE_STYLES = {"BPFO": "-", "BPFI": "--", "BSF": ":", "FTF": "-."}


def _panels(fig: MplFigure, count: int) -> list:
    axes = fig.subplots(count, 1, squeeze=False, sharex=True)[:, 0]
    return list(axes)


def envelope_figure(
    traces: list[SensorTrace], bandwidths: dict[str, float], lines: dict[str, float], title: str
) -> tuple[MplFigure, list[str]]:
    """One panel per sensor: envelope spectrum to 5 x BPFO with the defect lines."""
    fig = new_figure(11, 2.3 * len(traces) + 0.6)
    top = 5 * max(lines.values()) if lines else 500.0
    notes = []
    for ax, trace in zip(_panels(fig, len(traces)), traces, strict=True):
        band = envelope_band(trace.fs, bandwidths[trace.sensor])
        spec = envelope_spectrum(trace.signal, trace.fs, band)
        keep = (spec.freq > 2) & (spec.freq <= top)
        ax.plot(spec.freq[keep], spec.values[keep], lw=0.8, color="0.2")
        for name, freq in lines.items():
            ax.axvline(freq, color="tab:red", ls=_LINE_STYLES[name], lw=0.9, label=name)
        strongest = spec.freq[keep][np.argmax(spec.values[keep])]
        ax.set_title(f"{trace.sensor}: strongest line {strongest:.2f} Hz", fontsize=9, loc="left")
        ax.set_ylabel("envelope (g)")
        notes.append(f"{trace.sensor}: {spec.caption()}")
    ax.set_xlabel("frequency (Hz)")
    if lines:
        fig.axes[0].legend(fontsize=8, ncol=4, loc="upper right")
    fig.suptitle(title, fontsize=10)
    return fig, notes


def _velocity_figure(traces: list[SensorTrace], colors: dict[str, str], title: str):
    fig = new_figure(11, 3.6)
    ax = fig.subplots()
    notes = []
    for trace in traces:
        spec = velocity_spectrum(trace.signal, trace.fs)
        overall = float(np.sqrt(np.sum(spec.values**2)))
        ax.plot(
            spec.freq,
            spec.values,
            lw=0.8,
            color=colors.get(trace.sensor),
            label=f"{trace.sensor} ({overall:.2f} mm/s overall)",
        )
        notes.append(f"{trace.sensor}: {spec.caption()}")
    ax.set_yscale("log")
    ax.set_xlabel("frequency (Hz)")
    ax.set_ylabel("velocity (mm/s r.m.s.)")
    ax.legend(fontsize=8)
    ax.set_title(title, fontsize=10)
    return fig, notes


def _waterfall_figure(levels: list[tuple[str, list[SensorTrace]]], colors, title: str):
    sensors = [t.sensor for t in levels[0][1]]
    fig = new_figure(11, 2.4 * len(sensors) + 0.6)
    notes: dict[str, str] = {}
    shades = np.linspace(0.25, 1.0, len(levels))
    for ax, sensor in zip(_panels(fig, len(sensors)), sensors, strict=True):
        for (label, traces), shade in zip(levels, shades, strict=True):
            trace = next(t for t in traces if t.sensor == sensor)
            spec = asd(trace.signal, trace.fs)
            ax.plot(
                spec.freq[1:],
                spec.values[1:],
                lw=0.7,
                color=colors.get(sensor),
                alpha=float(shade),
                label=label,
            )
            notes[sensor] = spec.caption()
        ax.set_yscale("log")
        ax.set_xscale("log")
        ax.set_ylabel("ASD (g/√Hz)")
        ax.set_title(sensor, fontsize=9, loc="left")
        ax.legend(fontsize=7, ncol=len(levels))
    ax.set_xlabel("frequency (Hz)")
    fig.suptitle(title, fontsize=10)
    return fig, [f"{s}: {c}" for s, c in notes.items()]


def _worst(features: pd.DataFrame, reference: str, machine: str) -> pd.Series:
    rows = features[(features["sensor"] == reference) & (features["machine"] == machine)]
    means = rows.groupby("recording_id")["V_RMS"].mean()
    return rows[rows["recording_id"] == means.idxmax()].iloc[0]


def _envelope_blocks(mine: list, machine: str, specs: list, seed: int, figures_dir: Path):
    """One envelope figure per bearing-fault condition of ``machine`` (highest level)."""
    nominal = MACHINES[machine].shaft_hz if machine in MACHINES else None
    blocks: list[Block] = []
    for condition, (bearing, channel) in BEARING_RUNS.items():
        runs = [r for r in mine if r.condition == condition and r.channel == channel]
        if not runs or nominal is None:
            continue
        rec = max(runs, key=lambda r: r.severity or 0)
        x, traces = degrade_all(rec, specs, seed)
        shaft = running_speed(x, rec.sampling_rate_hz, nominal)
        lines = defect_frequencies(BEARINGS[bearing], shaft)
        title = (
            f"{machine} {rec.run} {channel}: envelope spectrum, {bearing} lines at "
            f"{shaft * 60:.0f} rpm"
        )
        bandwidths = {s.name: chain_bandwidth(s) for s in specs}
        fig, notes = envelope_figure(traces, bandwidths, lines, title)
        path = save_figure(fig, figures_dir, f"{slug('envelope', machine, condition)}.png")
        text = ", ".join(f"{k} {v:.2f} Hz" for k, v in lines.items())
        caption = (
            f"{title} (speed read off the reference's spectrum; nominal {nominal * 60:.0f} "
            f"rpm). Lines: {text}. " + "; ".join(notes) + "."
        )
        blocks.append(Figure(path, literal(caption), literal(title)))
    return blocks


def _velocity_blocks(mine: list, rec: Any, specs: list, seed: int, figures_dir, colors):
    """Velocity spectrum of ``rec`` and the waterfall of its fault family on its channel."""
    machine = rec.machine
    _, traces = degrade_all(rec, specs, seed)
    title = f"{machine} {rec.run} {rec.channel}: velocity spectrum 10-1000 Hz (worst-graded)"
    fig, notes = _velocity_figure(traces, colors, title)
    path = save_figure(fig, figures_dir, f"{slug('velocity', machine)}.png")
    caption = f"{title}. " + "; ".join(notes) + "."
    blocks: list[Block] = [Figure(path, literal(caption), literal(title))]
    family = [r for r in mine if r.condition == rec.condition and r.channel == rec.channel]
    healthy = [r for r in mine if r.severity is None and r.channel == rec.channel][:1]
    levels = [
        (f"{r.run}", degrade_all(r, specs, seed)[1])
        for r in healthy + sorted(family, key=lambda r: r.severity or 0)
    ]
    title = f"{machine} {rec.channel}: severity waterfall, {rec.condition} levels and healthy"
    fig, notes = _waterfall_figure(levels, colors, title)
    path = save_figure(fig, figures_dir, f"{slug('waterfall', machine)}.png")
    caption = f"{title}. " + "; ".join(notes) + "."
    blocks.append(Figure(path, literal(caption), literal(title)))
    return blocks


def spectral_blocks(
    folder: ResultsFolder, registry: Any, figures_dir: Path, colors: dict[str, str]
) -> list[Block]:
    """Envelope, velocity and waterfall figures per machine; a note when they cannot be drawn."""
    blocks: list[Block] = [Heading("Spectra", 3)]
    if folder.config is None or folder.features is None:
        return [*blocks, Paragraph("Not drawn: config.toml or features.parquet is missing.")]
    try:
        specs = [registry.sensor(name) for name in folder.sensors]
        recordings = {r.recording_id: r for r in open_config_dataset(folder.config, registry)}
    except SDTError as exc:
        return [*blocks, Paragraph(f"Not drawn: {literal(exc)}")]
    seed = folder.config.seed
    features = folder.features
    for machine in sorted(features["machine"].unique()):
        mine = [r for r in recordings.values() if r.machine == machine]
        blocks += _envelope_blocks(mine, machine, specs, seed, figures_dir)
        rec = recordings.get(_worst(features, folder.reference, machine)["recording_id"])
        if rec is not None:
            blocks += _velocity_blocks(mine, rec, specs, seed, figures_dir, colors)
    return blocks
