"""The envelope figure draws the ball-defect line at 2 x BSF and says where its resonance lands.

Issue 40: BSF was drawn at 1 x where ball defects show at 2 x; and the MEMS
envelopes of the paper's model showed BPFO from a resonance above their
output Nyquist, folded into their envelope band, without a word.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sdt_plugins.datasets.synthetic_pump.model import CHANNELS, MOTOR_BEARING

from sdt_framework.chain import degrade
from sdt_framework.report.figures_envelope import envelope_figure, envelope_notes
from sdt_framework.report.signals import degrade_all
from sdt_framework.report.style import save_figure
from sdt_framework.severity import defect_lines
from sdt_framework.specs import BearingSpec

from .conftest import assert_real_png

#: Case Western Reserve University Bearing Data Center, drive-end 6205-2RS JEM SKF: defect
#: frequencies as multiples of running speed (inner ring, outer ring, cage, rolling element)
CWRU = {"BPFI": 5.4152, "BPFO": 3.5848, "FTF": 0.39828, "ball": 4.7135}


def test_ball_defect_line_is_twice_bsf_as_the_cwru_table_gives_it() -> None:
    # the table's own BPFI + BPFO = n and BPFI - BPFO = n d/D give the geometry
    balls = round(CWRU["BPFI"] + CWRU["BPFO"])
    ratio = (CWRU["BPFI"] - CWRU["BPFO"]) / balls
    bearing = BearingSpec(
        name="6205", balls=balls, ball_mm=ratio * 100, pitch_mm=100.0, channel="DE", faults=()
    )
    lines = defect_lines(bearing, 1.0)
    assert set(lines) == {"BPFO", "BPFI", "2×BSF", "FTF"}
    assert lines["2×BSF"] == pytest.approx(CWRU["ball"], abs=2e-4)
    for name in ("BPFO", "BPFI", "FTF"):
        assert lines[name] == pytest.approx(CWRU[name], abs=2e-4)


def _recording(channel: str, condition: str):
    (rec,) = open_synthetic(
        machines="Motor-2", channels=channel, conditions=condition, duration=2
    ).recordings()[-1:]
    assert rec.severity == 3
    return rec


@pytest.fixture(scope="module")
def outer_race(registry):
    """Synthetic Motor-2 outer-race fault, level 3, ch2, through the reference and two ADXL357s."""
    rec = _recording("ch2", "bearing bpfo")
    paper = registry.sensor("adxl357")
    decimating = paper.model_copy(update={"name": "adxl357-dec", "sampling": "decimate"})
    specs = [registry.sensor("wilcoxon-786b10"), paper, decimating]
    x, traces = degrade_all(rec, specs, seed=0)
    return rec, specs, x, traces


def _butterworth_db(f: float, cutoff: float, order: int) -> float:
    """|H| of an analog Butterworth low-pass in dB, by hand."""
    return -10 * np.log10(1 + (f / cutoff) ** (2 * order))


def _simulated_aliased_share(spec, x, fs, envelope_hz) -> float:
    """Independent: run the chain (no noise) on x and on x with everything above the output
    Nyquist removed; the share of the envelope band's power that goes is the aliased share."""
    nyquist = spec.sampling_rate_hz / 2
    sos = signal.ellip(12, 0.01, 120, 0.98 * nyquist, fs=fs, output="sos")

    def band_power(inp):
        y, fs_out = degrade(inp, fs, spec, 0, noise=False)
        freq, psd = signal.welch(y, fs=fs_out, nperseg=256)
        return psd[(freq >= envelope_hz[0]) & (freq <= envelope_hz[1])].sum()

    return 1 - band_power(signal.sosfiltfilt(sos, x)) / band_power(x)


def test_envelope_says_the_paper_adxl357_shows_aliased_content(outer_race, tmp_path) -> None:
    rec, specs, x, traces = outer_race
    fs = rec.sampling_rate_hz
    bands, content, caption = envelope_notes(x, fs, specs, traces)
    paper, decimating = content["adxl357"], content["adxl357-dec"]
    # what reaches the envelope band agrees with the chain run on the recording itself
    for spec in specs[1:]:
        simulated = _simulated_aliased_share(spec, x, fs, bands[spec.name])
        assert content[spec.name].aliased_share == pytest.approx(simulated, abs=0.05)
    assert paper.aliased_share > 0.9 and paper.aliased_into_envelope
    assert decimating.aliased_share < 0.01 and not decimating.aliased_into_envelope
    # the source is the generator's first housing mode of ch2: 3600 Hz, damping 0.035
    mode_hz, zeta, _ = CHANNELS["ch2"].modes[0]
    lo, hi = paper.source.band_hz
    assert lo < mode_hz < hi and hi - lo < 2 * (2 * zeta * mode_hz)
    # independent: above the 2000 Hz Nyquist, f lands at 4000 - f
    assert paper.source.folded_hz == pytest.approx((4000 - hi, 4000 - lo), abs=0.5)
    # its gain at the band's lowest line: mechanical 2nd order at 5500 Hz, analog 1st order at
    # 1500 Hz, then the 8th-order 1000 Hz low-pass at the folded frequency
    expected = (
        _butterworth_db(lo, 5500, 2) + _butterworth_db(lo, 1500, 1)
        + _butterworth_db(4000 - lo, 1000, 8)
    )  # fmt: skip
    assert paper.source.gain_db == pytest.approx(expected, abs=1.0)
    # the decimating part names the recording's strongest resonance, which it attenuates: the
    # 8th-order low-pass meets it at its own frequency, before sampling
    r_lo, r_hi = decimating.source.band_hz
    assert r_lo < mode_hz < r_hi and decimating.source.kind == "attenuated"
    assert decimating.source.gain_db < _butterworth_db(r_lo, 1000, 8) + 1.0
    assert content["wilcoxon-786b10"].aliased_share == 0.0
    assert content["wilcoxon-786b10"].source.kind == "passed"
    folded = f"folded to {4000 - hi:.0f}-{4000 - lo:.0f} Hz at {paper.source.gain_db:+.1f} dB"
    assert folded in caption and "this envelope shows aliased content" in caption
    assert f"attenuated by {-decimating.source.gain_db:.0f} dB (decimate" in caption

    lines = defect_lines(MOTOR_BEARING, 24.65)  # the 6309: 8 balls of 17.46 mm on 72.5 mm
    fig, _ = envelope_figure(traces, bands, lines, "outer race", content)
    panel_text = {ax.get_title(loc="left").split(":")[0]: ax.texts for ax in fig.axes}
    (note,) = panel_text["adxl357"]
    assert note.get_text().startswith(f"envelope band {paper.aliased_share:.0%} aliased: ")
    assert note.get_color() == "tab:red"
    (note,) = panel_text["adxl357-dec"]
    assert note.get_text().endswith(f"attenuated by {-decimating.source.gain_db:.0f} dB")
    ball = [ln for ln in fig.axes[0].lines if ln.get_label() == "2×BSF"]
    assert ball and ball[0].get_xdata()[0] == pytest.approx(lines["2×BSF"])
    assert "BSF" not in [ln.get_label() for ln in fig.axes[0].lines]
    assert_real_png(save_figure(fig, tmp_path, "envelope.png"))


def test_envelope_counts_every_folded_resonance_not_only_the_strongest(registry) -> None:
    """Pump bearing, ch4: the 4.3 kHz mode's peak folds through the ADXL345 to 0.9-1.3 kHz,
    outside its 200-800 Hz envelope band, yet most of that band is aliased (mostly the mode's
    lower skirt, 3.7-4.1 kHz; the 6.1 kHz mode adds about a tenth): it must not read clean."""
    rec = _recording("ch4", "bearing pump")
    spec = registry.sensor("adxl345")
    x, traces = degrade_all(rec, [spec], seed=0)
    bands, content, _ = envelope_notes(x, rec.sampling_rate_hz, [spec], traces)
    simulated = _simulated_aliased_share(spec, x, rec.sampling_rate_hz, bands["adxl345"])
    assert simulated > 0.5
    assert content["adxl345"].aliased_share == pytest.approx(simulated, abs=0.05)
    assert content["adxl345"].aliased_into_envelope
