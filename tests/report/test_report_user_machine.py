"""A user's own machine, given in machines.toml beside the manifest, gets its envelope figure.

The data: a manifest of ``pump-A`` recordings on channel ``DE-h`` at 20 kHz, a
healthy run and three levels of an outer-race fault made here from the
physics (a 1x line at 30 Hz, impacts at the BPFO of a 6205 ringing a 3 kHz
resonance). The user's ``machines.toml`` names the 6205 (9 balls of 7.94 mm
on a 39.04 mm pitch circle), its channel and the condition label of its
fault. Before the rig became data the report drew envelope figures only for
the pump rig's condition names and machine names, so this machine got no
figure and no word why; now it gets its bearing's lines at the running speed
read off the spectrum (BPFO = 9/2 (1 - 7.94/39.04) x 30 Hz = 107.5 Hz,
computed here by hand) and, for a machine without a spec, one line naming
what to add.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from sdt_framework import build_registry
from sdt_framework.bench.config import load_config
from sdt_framework.data import open_manifest
from sdt_framework.labels import slug
from sdt_framework.report.document import Figure, Paragraph
from sdt_framework.report.figures_severity import spectral_blocks
from sdt_framework.report.load import ResultsFolder

FS, SHAFT_HZ, SECONDS = 20000.0, 30.0, 2.0
BALLS, BALL_MM, PITCH_MM = 9, 7.94, 39.04
BPFO_HZ = BALLS / 2 * (1 - BALL_MM / PITCH_MM) * SHAFT_HZ  # 107.54 Hz
COLORS = {"wilcoxon-786b10": "black"}

MACHINES_TOML = f"""
[machine."pump-A"]
shaft_rpm = {SHAFT_HZ * 60}
zone_table = "iso10816-3-group2-rigid"
zone_why = "our 30 kW pump on a concrete block"

[[machine."pump-A".bearings]]
name = "6205"
balls = {BALLS}
ball_mm = {BALL_MM}
pitch_mm = {PITCH_MM}
channel = "DE-h"
faults = ["outer race"]
source = "the maker's catalogue"
"""


def _signal(level: int, seed: int) -> np.ndarray:
    """Two acquisitions in g: 1x at 30 Hz, noise, and (level > 0) impacts at BPFO at 3 kHz."""
    gen = np.random.default_rng(seed)
    t = np.arange(int(SECONDS * FS)) / FS
    x = 0.05 * np.sin(2 * np.pi * SHAFT_HZ * t) + 0.01 * gen.standard_normal(t.size)
    if level:
        ring = np.exp(-t[:400] * 600) * np.sin(2 * np.pi * 3000 * t[:400])
        train = np.zeros(t.size)
        times = np.arange(0.0, SECONDS, 1 / BPFO_HZ)
        train[np.rint(times * FS).astype(int) % t.size] = 0.5 * level
        x = x + np.convolve(train, ring)[: t.size]
    return np.stack([x, x[::-1].copy()])


def _manifest(folder: Path, machine: str = "pump-A") -> Path:
    rows = ["path,sampling_rate_hz,machine,condition,severity,recording_id,channel"]
    runs = [("h1", "healthy", 0), *[(f"o{k}", "outer race", k) for k in (1, 2, 3)]]
    for run, condition, level in runs:
        np.save(folder / f"{run}.npy", _signal(level, seed=level))
        rows.append(f"{run}.npy,{FS:g},{machine},{condition},{level or ''},{run},DE-h")
    (folder / "manifest.csv").write_text("\n".join(rows) + "\n")
    return folder / "manifest.csv"


def _results_folder(tmp_path: Path, manifest: Path) -> ResultsFolder:
    """The folder a benchmark of ``manifest`` by the reference chain leaves, as the report
    reads it: its config, and features whose V_RMS picks the worst recording."""
    dataset = open_manifest(manifest, readers=build_registry().signal_readers())
    rows = [
        {"machine": r.machine, "sensor": "wilcoxon-786b10", "recording_id": r.recording_id,
         "V_RMS": float(1 + (r.severity or 0))}
        for r in dataset.recordings()
    ]  # fmt: skip
    results = pd.DataFrame(
        [("pump-A", "forward", "wilcoxon-786b10", "lr", 0.5, "ok")],
        columns=["machine", "scenario", "sensor", "classifier", "macro_f1", "status"],
    )
    folder = ResultsFolder(tmp_path / "results", results, features=pd.DataFrame(rows))
    folder.config = load_config(None, {"data": str(manifest), "sensors": ["wilcoxon-786b10"]})
    return folder


@pytest.fixture(scope="module")
def registry():
    return build_registry()


def test_a_users_bearing_gets_an_envelope_figure_with_its_lines(tmp_path, registry) -> None:
    manifest = _manifest(tmp_path)
    (tmp_path / "machines.toml").write_text(MACHINES_TOML)
    assert (
        open_manifest(manifest, readers=registry.signal_readers())
        .machines["pump-A"]
        .bearings[0]
        .name
        == "6205"
    )
    folder = _results_folder(tmp_path, manifest)
    blocks = spectral_blocks(folder, registry, tmp_path / "figures", COLORS)
    envelopes = [b for b in blocks if isinstance(b, Figure) and "envelope" in b.path.name]
    assert [b.path.name for b in envelopes] == [slug("envelope", "pump-A", "outer race") + ".png"]
    (figure,) = envelopes
    assert figure.path.is_file()
    caption = figure.caption
    assert caption.startswith("pump-A o3 DE-h: envelope spectrum, 6205 lines at 1800 rpm")
    assert "nominal 1800 rpm" in caption
    bpfo = float(re.search(r"BPFO (\d+\.\d+) Hz", caption).group(1))
    assert bpfo == pytest.approx(BPFO_HZ, abs=0.1)  # 107.54 Hz
    bsf2 = float(re.search(r"2×BSF (\d+\.\d+) Hz", caption).group(1))
    ratio = BALL_MM / PITCH_MM
    assert bsf2 == pytest.approx(2 * PITCH_MM / (2 * BALL_MM) * (1 - ratio**2) * SHAFT_HZ, abs=0.1)


def test_a_machine_without_a_spec_is_one_line_naming_what_to_add(tmp_path, registry) -> None:
    manifest = _manifest(tmp_path)  # no machines.toml
    folder = _results_folder(tmp_path, manifest)
    blocks = spectral_blocks(folder, registry, tmp_path / "figures", COLORS)
    assert not any(isinstance(b, Figure) and "envelope" in b.path.name for b in blocks)
    (line,) = [b.text for b in blocks if isinstance(b, Paragraph) and "machine spec" in b.text]
    assert line.startswith("pump-A: no machine spec, so no bearing defect lines")
    assert "machines.toml beside the manifest" in line
    assert '[benchmark.machine\\_specs."pump-A"\\]' in line  # markdown-escaped


def test_a_spec_whose_fault_labels_are_not_in_the_data_says_so(tmp_path, registry) -> None:
    manifest = _manifest(tmp_path)
    (tmp_path / "machines.toml").write_text(MACHINES_TOML.replace('"outer race"', '"BPFO"'))
    folder = _results_folder(tmp_path, manifest)
    blocks = spectral_blocks(folder, registry, tmp_path / "figures", COLORS)
    (line,) = [b.text for b in blocks if isinstance(b, Paragraph) and "6205" in b.text]
    assert "no envelope figure: none of its faults (BPFO) is a condition of the data" in line
    assert "healthy, outer race" in line
