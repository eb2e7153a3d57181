"""The envelope figure draws the ball-defect line at 2 x BSF and says where its resonance lands.

Issue 40: BSF was drawn at 1 x where ball defects show at 2 x; and the MEMS
envelopes of the paper's model showed BPFO from a resonance above their
output Nyquist, folded into their envelope band, without a word.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from sdt_framework.data import open_synthetic
from sdt_framework.data.synth_model import CHANNELS, Bearing
from sdt_framework.report.figures_severity import drawn_lines, envelope_figure, envelope_notes
from sdt_framework.report.signals import degrade_all
from sdt_framework.report.style import save_figure
from sdt_framework.severity import defect_frequencies

from .conftest import assert_real_png

#: Case Western Reserve University Bearing Data Center, drive-end 6205-2RS JEM SKF: defect
#: frequencies as multiples of running speed (inner ring, outer ring, cage, rolling element)
CWRU = {"BPFI": 5.4152, "BPFO": 3.5848, "FTF": 0.39828, "ball": 4.7135}


def test_ball_defect_line_is_twice_bsf_as_the_cwru_table_gives_it() -> None:
    # the table's own BPFI + BPFO = n and BPFI - BPFO = n d/D give the geometry
    balls = round(CWRU["BPFI"] + CWRU["BPFO"])
    ratio = (CWRU["BPFI"] - CWRU["BPFO"]) / balls
    lines = drawn_lines(defect_frequencies(Bearing("6205", balls, ratio * 100, 100.0), 1.0))
    assert set(lines) == {"BPFO", "BPFI", "2×BSF", "FTF"}
    assert lines["2×BSF"] == pytest.approx(CWRU["ball"], abs=2e-4)
    for name in ("BPFO", "BPFI", "FTF"):
        assert lines[name] == pytest.approx(CWRU[name], abs=2e-4)


@pytest.fixture(scope="module")
def outer_race(registry):
    """Synthetic Motor-2 outer-race fault, level 3, ch2, through the reference and two ADXL357s."""
    (rec,) = open_synthetic(
        machines="Motor-2", channels="ch2", conditions="bearing bpfo", duration=2
    ).recordings()[-1:]
    paper = registry.sensor("adxl357")
    decimating = paper.model_copy(update={"name": "adxl357-dec", "sampling": "decimate"})
    specs = [registry.sensor("wilcoxon-786b10"), paper, decimating]
    x, traces = degrade_all(rec, specs, seed=0)
    return rec, specs, x, traces


def _butterworth_db(f: float, cutoff: float, order: int) -> float:
    """|H| of an analog Butterworth low-pass in dB, by hand."""
    return -10 * np.log10(1 + (f / cutoff) ** (2 * order))


def test_envelope_says_the_paper_adxl357_shows_aliased_content(outer_race, tmp_path) -> None:
    rec, specs, x, traces = outer_race
    assert rec.severity == 3
    bands, fates, caption = envelope_notes(x, rec.sampling_rate_hz, specs, traces)
    # the generator rings ch2's first housing mode: 3600 Hz, damping 0.035 (synth_model)
    mode_hz, zeta, _ = CHANNELS["ch2"].modes[0]
    lo, hi = fates["adxl357"].fate.band_hz
    assert lo < mode_hz < hi
    assert 0.5 < (hi - lo) / (2 * zeta * mode_hz) < 2.0  # half-power width 2 zeta f
    paper = fates["adxl357"]
    assert paper.fate.kind == "aliased" and paper.aliased_into_envelope
    # independent: above the 2000 Hz Nyquist, f lands at 4000 - f
    assert paper.fate.folded_hz == pytest.approx((4000 - hi, 4000 - lo), abs=0.5)
    # its gain at the band's lowest line: mechanical 2nd order at 5500 Hz, analog 1st order at
    # 1500 Hz, then the 8th-order 1000 Hz low-pass at the folded frequency
    expected = (
        _butterworth_db(lo, 5500, 2)
        + _butterworth_db(lo, 1500, 1)
        + _butterworth_db(4000 - lo, 1000, 8)
    )
    assert paper.fate.gain_db == pytest.approx(expected, abs=1.0)
    decimating = fates["adxl357-dec"]
    assert decimating.fate.kind == "attenuated" and not decimating.aliased_into_envelope
    # the 8th-order low-pass now meets the resonance at its own frequency, before sampling
    assert decimating.fate.gain_db < expected + _butterworth_db(lo, 1000, 8) + 1.0
    assert fates["wilcoxon-786b10"].fate.kind == "passed"
    # the signals agree: the paper's model carries the folded resonance into its envelope band
    powers = {}
    for trace in traces[1:]:
        freq, psd = signal.welch(trace.signal, fs=trace.fs, nperseg=1024)
        keep = (freq >= 4000 - hi) & (freq <= 4000 - lo)
        powers[trace.sensor] = psd[keep].sum()
    assert powers["adxl357"] > 30 * powers["adxl357-dec"]
    text = f"folds to {4000 - hi:.0f}-{4000 - lo:.0f} Hz at {paper.fate.gain_db:+.1f} dB"
    assert text in caption and "this envelope shows aliased content" in caption
    assert f"attenuated by {-decimating.fate.gain_db:.0f} dB (decimate)" in caption

    lines = drawn_lines(defect_frequencies(Bearing("6309", 8, 17.46, 72.5), 24.65))
    fig, _ = envelope_figure(traces, bands, lines, "outer race", fates)
    panel_text = {ax.get_title(loc="left").split(":")[0]: ax.texts for ax in fig.axes}
    (note,) = panel_text["adxl357"]
    assert note.get_text().startswith(f"resonance aliased to {4000 - hi:.0f}-{4000 - lo:.0f} Hz")
    assert note.get_color() == "tab:red"
    (note,) = panel_text["adxl357-dec"]
    assert note.get_text() == f"resonance attenuated by {-decimating.fate.gain_db:.0f} dB"
    ball = [ln for ln in fig.axes[0].lines if ln.get_label() == "2×BSF"]
    assert ball and ball[0].get_xdata()[0] == pytest.approx(lines["2×BSF"])
    assert "BSF" not in [ln.get_label() for ln in fig.axes[0].lines]
    assert_real_png(save_figure(fig, tmp_path, "envelope.png"))
