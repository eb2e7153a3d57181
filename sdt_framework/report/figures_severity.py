"""The spectra the field reads, per machine and sensor: envelope, velocity, spectra by level.

Recordings are re-opened from the configuration and passed through every
sensor's chain as for Fig. 2 (:mod:`.signals`), first acquisition, the
benchmark's seed. Each caption states the scaling, window, resolution
bandwidth and unit of every spectrum drawn (:class:`~sdt_framework.severity.Spectrum`).

- Envelope spectrum of each bearing-fault run (highest level): band-pass
  under each chain's bandwidth (:func:`~sdt_framework.severity.envelope_band`),
  Hilbert envelope, with the bearing's BPFO, BPFI, 2 x BSF and FTF at the
  running speed read off the reference's spectrum; each panel says where the
  resonance the impacts ring lands in that chain (:mod:`.resonance`): passed,
  attenuated, or aliased into its envelope band.
- Velocity spectrum 10-1000 Hz (mm/s r.m.s. per line) of the recording the
  reference grades worst (largest mean V_RMS), each sensor's band cut to what
  its chain passes (:mod:`.passband`).
- Spectra by fault level (:mod:`.figures_levels`): ASD of the healthy runs and
  of each level of that recording's fault, on its channel, one panel per sensor.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.figure import Figure as MplFigure

from ..chain import passband
from ..data.synth_model import MACHINES
from ..errors import SDTError
from ..labels import slug
from ..severity import (
    BEARINGS,
    chain_bandwidth,
    defect_lines,
    envelope_band,
    envelope_spectrum,
    running_speed,
    velocity_spectrum,
)
from .document import Block, Figure, Heading, Paragraph, literal
from .figures_levels import MAX_TESTS, Level, levels_figure
from .load import ResultsFolder
from .resonance import EnvelopeContent, envelope_content, excited_band
from .signals import SensorTrace, degrade_all, open_config_dataset
from .style import figure_label, new_figure, save_figure

__all__ = [
    "BEARING_RUNS",
    "VELOCITY_BAND_HZ",
    "envelope_figure",
    "envelope_notes",
    "spectral_blocks",
]

#: bearing-fault condition -> (bearing, channel nearest to it in the NLN-EMP layout)
BEARING_RUNS = {
    "bearing bpfo": ("6309", "ch2"),
    "bearing bpfi": ("6309", "ch2"),
    "bearing pump": ("6308", "ch4"),
}
_LINE_STYLES = {"BPFO": "-", "BPFI": "--", "2×BSF": ":", "FTF": "-."}
VELOCITY_BAND_HZ = (10.0, 1000.0)


def _panels(fig: MplFigure, count: int) -> list:
    axes = fig.subplots(count, 1, squeeze=False, sharex=True)[:, 0]
    return list(axes)


def envelope_figure(
    traces: list[SensorTrace],
    bands: dict[str, tuple[float, float]],
    lines: dict[str, float],
    title: str,
    fates: dict[str, EnvelopeContent] | None = None,
) -> tuple[MplFigure, list[str]]:
    """One panel per sensor: envelope spectrum to 5 x BPFO with the defect lines.

    ``bands`` is each sensor's envelope band, ``lines`` the lines to draw (see
    :func:`~sdt_framework.severity.defect_lines`); with ``fates`` each panel says what
    its envelope band holds (:class:`.resonance.EnvelopeContent`), in red when mostly
    aliased content.
    """
    fig = new_figure(11, 2.3 * len(traces) + 0.6)
    top = 5 * max(lines.values()) if lines else 500.0
    notes = []
    for ax, trace in zip(_panels(fig, len(traces)), traces, strict=True):
        spec = envelope_spectrum(trace.signal, trace.fs, bands[trace.sensor])
        keep = (spec.freq > 2) & (spec.freq <= top)
        ax.plot(spec.freq[keep], spec.values[keep], lw=0.8, color="0.2")
        for name, freq in lines.items():
            ax.axvline(freq, color="tab:red", ls=_LINE_STYLES.get(name, ":"), lw=0.9, label=name)
        strongest = spec.freq[keep][np.argmax(spec.values[keep])]
        name = figure_label(trace.sensor)
        ax.set_title(f"{name}: strongest line {strongest:.2f} Hz", fontsize=9, loc="left")
        fate = (fates or {}).get(trace.sensor)
        if fate is not None:
            ax.text(
                0.005,
                0.96,
                fate.short(),
                transform=ax.transAxes,
                ha="left",
                va="top",
                fontsize=8,
                color="tab:red" if fate.aliased_into_envelope else "0.3",
                bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 1.5},
            )
        ax.set_ylabel(f"envelope ({spec.unit})")
        notes.append(f"{trace.sensor}: {spec.caption()}")
    ax.set_xlabel("frequency (Hz)")
    if lines:
        fig.axes[0].legend(fontsize=8, ncol=4, loc="upper right")
    fig.suptitle(title, fontsize=10)
    return fig, notes


def envelope_notes(
    x: np.ndarray, fs: float, specs: list, traces: list[SensorTrace]
) -> tuple[dict[str, tuple[float, float]], dict[str, EnvelopeContent], str]:
    """Each sensor's envelope band, what reaches it from the recording, and a caption.

    The resonance named where nothing aliased arrives is read off the recording
    ``x`` at ``fs`` (:func:`.resonance.excited_band`) within the band the
    reference's envelope uses at this rate.
    """
    pairs = zip(traces, specs, strict=True)
    bands = {t.sensor: envelope_band(t.fs, chain_bandwidth(s)) for t, s in pairs}
    search = envelope_band(fs, fs / 2)
    try:
        resonance = excited_band(x, fs, search)
        fates = {s.name: envelope_content(s, x, fs, bands[s.name], resonance) for s in specs}
    except ValueError as exc:  # a recording too short or too slow to hold the band
        return bands, {}, f"Envelope content not located ({exc})."
    text = (
        f"What each envelope band holds, line by line from the recording's spectrum "
        f"through each chain's gain and folding (strongest resonance {resonance[0]:.0f}-"
        f"{resonance[1]:.0f} Hz, in {search[0]:.0f}-{search[1]:.0f} Hz): "
        + "; ".join(f.describe() for f in fates.values())
        + "."
    )
    return bands, fates, text


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
        lines = defect_lines(BEARINGS[bearing], shaft)
        title = (
            f"{machine} {rec.run} {channel}: envelope spectrum, {bearing} lines at "
            f"{shaft * 60:.0f} rpm"
        )
        bands, fates, resonance = envelope_notes(x, rec.sampling_rate_hz, specs, traces)
        fig, notes = envelope_figure(traces, bands, lines, title, fates)
        path = save_figure(fig, figures_dir, f"{slug('envelope', machine, condition)}.png")
        text = ", ".join(f"{k} {v:.2f} Hz" for k, v in lines.items())
        caption = (
            f"{title} (speed read off the reference's spectrum; nominal {nominal * 60:.0f} "
            f"rpm). Lines: {text} (a ball defect strikes both races once per spin "
            f"revolution: its line is 2×BSF). {resonance} " + "; ".join(notes) + "."
        )
        blocks.append(Figure(path, literal(caption), literal(title)))
    return blocks


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
