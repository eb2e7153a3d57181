"""The envelope figures of the report: each bearing fault of a machine's spec, every sensor.

For each bearing of the machine's spec (:mod:`.machines`: the dataset's own,
or the user's), each of its faults the data holds on the bearing's channel,
highest level: band-pass under each chain's bandwidth
(:func:`~sdt_framework.severity.envelope_band`), Hilbert envelope, the
bearing's BPFO, BPFI, 2 x BSF and FTF at the running speed read off the
reference's spectrum near the spec's shaft speed; each panel says where the
resonance the impacts ring lands in that chain (:mod:`.resonance`). A machine
without a spec, or a bearing none of whose faults has a recording on its
channel, is one line saying so.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.figure import Figure as MplFigure

from ..labels import slug
from ..severity import (
    chain_bandwidth,
    defect_lines,
    envelope_band,
    envelope_spectrum,
    running_speed,
)
from ..specs import BearingSpec, MachineSpec
from .document import Block, Figure, Paragraph, literal
from .machines import no_spec_line
from .resonance import EnvelopeContent, envelope_content, excited_band
from .signals import SensorTrace, degrade_all
from .style import figure_label, new_figure, save_figure

__all__ = ["envelope_blocks", "envelope_figure", "envelope_notes"]

_LINE_STYLES = {"BPFO": "-", "BPFI": "--", "2×BSF": ":", "FTF": "-."}


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


def _bearing_note(machine: str, bearing: BearingSpec, mine: list) -> Paragraph | None:
    """Why a bearing of the spec gets no figure, or None when one of its faults has runs."""
    held = {r.condition for r in mine}
    faults = [f for f in bearing.faults if f in held]
    if any(r.condition in faults and r.channel == bearing.channel for r in mine):
        return None
    if faults:
        why = f"its faults {', '.join(faults)} have no recording on its channel {bearing.channel}"
    else:
        why = (
            f"none of its faults ({', '.join(bearing.faults) or 'none listed'}) is a condition "
            f"of the data ({', '.join(sorted(held))})"
        )
    return Paragraph(literal(f"{machine} bearing {bearing.name}: no envelope figure: {why}."))


def envelope_blocks(
    mine: list, machine: str, spec: MachineSpec | None, specs: list, seed: int, figures_dir: Path
) -> list[Block]:
    """One envelope figure per bearing-fault condition of ``machine`` (highest level), on the
    bearing's channel, the lines of the bearing its spec names; a line when none can be drawn."""
    if spec is None:
        return [Paragraph(literal(no_spec_line(machine) + "."))]
    blocks: list[Block] = []
    for bearing in spec.bearings:
        note = _bearing_note(machine, bearing, mine)
        if note is not None:
            blocks.append(note)
            continue
        for condition in bearing.faults:
            runs = [r for r in mine if r.condition == condition and r.channel == bearing.channel]
            if runs:
                blocks.append(
                    _envelope_block(runs, machine, spec, bearing, specs, seed, figures_dir)
                )
    return blocks


def _envelope_block(runs, machine, spec, bearing, specs, seed, figures_dir) -> Figure:
    """The envelope figure of the highest level of one bearing fault's runs."""
    nominal, channel, condition = spec.shaft_hz, bearing.channel, runs[0].condition
    rec = max(runs, key=lambda r: r.severity or 0)
    x, traces = degrade_all(rec, specs, seed)
    shaft = running_speed(x, rec.sampling_rate_hz, nominal)
    lines = defect_lines(bearing, shaft)
    title = (
        f"{machine} {rec.run} {channel}: envelope spectrum, {bearing.name} lines at "
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
    return Figure(path, literal(caption), literal(title))
