"""Envelope spectrum of the synthetic Motor-2 outer-race fault: the 6309's BPFO, per sensor.

The defect frequency is computed here from the bearing geometry the generator
uses (8 balls of 17.46 mm on a 72.5 mm pitch circle, docs/data.md) at the
nominal 1480 rpm, with the run-to-run speed scatter switched off so that the
nominal speed is the true one (within the 0.05 % acquisition jitter, a tenth
of a bin here). Each sensor's chain is the product's (registry), and the
envelope band sits under each chain's bandwidth (envelope_band).

The MEMS chains find BPFO only through aliasing (issue 40): the fault rings
the housing's 3.6 kHz resonance, above both parts' output Nyquist. The paper's
models sample with no decimation filter, so the resonance folds into their
125-800 Hz envelope bands (to 400 Hz at 4 kHz) and carries the impacts there.
A real sigma-delta part filters before it decimates: the decimating ADXL357
(the catalogue's ``adxl357-ds``) attenuates the resonance by about 100 dB and
its envelope shows no BPFO line, which the last test states.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal
from sdt_plugins.datasets.synthetic_pump import model as model
from sdt_plugins.datasets.synthetic_pump import open_synthetic

from sdt_framework.api import degrade
from sdt_framework.severity import (
    chain_bandwidth,
    envelope_band,
    envelope_spectrum,
    running_speed,
)

BPFO_6309 = 8 / 2 * (1 - 17.46 / 72.5) * 1480 / 60  # 74.905 Hz


@pytest.fixture(scope="module")
def outer_race_fault() -> tuple[np.ndarray, float]:
    """Motor-2 'bearing bpfo 3' (highest level), ch2 (motor drive end), 4 s at 20 kHz."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(model, "SPEED_JITTER", 0.0)
        ds = open_synthetic(seed=0, duration=4.0, machines="Motor-2", conditions="bearing bpfo")
        (rec,) = [r for r in ds.recordings() if r.run == "bearing bpfo 3" and r.channel == "ch2"]
        return rec.load()[0], rec.sampling_rate_hz


@pytest.mark.parametrize("sensor", ["wilcoxon-786b10", "adxl345", "adxl357"])
def test_strongest_envelope_line_is_the_6309_bpfo_within_one_bin(
    outer_race_fault, registry, sensor: str
) -> None:
    x, fs = outer_race_fault
    spec = registry.sensor(sensor)
    y, fs_out = degrade(x, fs, spec, 0)
    env = envelope_spectrum(y, fs_out, envelope_band(fs_out, chain_bandwidth(spec)))
    shown = (env.freq > 2) & (env.freq <= 400)
    strongest = env.freq[shown][np.argmax(env.values[shown])]
    assert abs(strongest - BPFO_6309) <= env.bin_hz
    assert env.bin_hz == pytest.approx(0.25)  # 4 s: the caption's line spacing
    window = signal.windows.flattop(y.size, sym=False)
    enbw = y.size * np.sum(window**2) / np.sum(window) ** 2  # 3.77 lines: the flat-top's
    assert env.rbw_hz == pytest.approx(enbw * 0.25)


def test_running_speed_read_off_the_spectrum_is_the_nominal_one(outer_race_fault) -> None:
    x, fs = outer_race_fault
    # speed scatter off: the generator runs at 1480 rpm x (1 +- 0.15 % at most)
    assert running_speed(x, fs, 1480 / 60) * 60 == pytest.approx(1480, rel=0.0015)


@pytest.mark.catalog
def test_a_decimating_adxl357_sees_no_bpfo_in_its_envelope(outer_race_fault, registry) -> None:
    """What a real ADXL357 would show: its decimation filter removes the 3.6 kHz resonance
    before the 4 kHz output, so no impact train reaches its 125-500 Hz band and the BPFO
    line is not the strongest, nor above the envelope's own spread (the paper's model,
    which folds the resonance in, stands over 10 times its median at BPFO)."""
    x, fs = outer_race_fault
    levels = {}
    for name in ("adxl357", "adxl357-ds"):
        spec = registry.sensor(name)
        y, fs_out = degrade(x, fs, spec, 0)
        env = envelope_spectrum(y, fs_out, envelope_band(fs_out, chain_bandwidth(spec)))
        shown = (env.freq > 2) & (env.freq <= 400)
        at_bpfo = np.abs(env.freq - BPFO_6309) <= env.bin_hz
        levels[name] = (
            env.freq[shown][np.argmax(env.values[shown])],
            env.values[at_bpfo].max() / np.median(env.values[shown]),
        )
    assert registry.sensor("adxl357-ds").sampling == "decimate"
    assert abs(levels["adxl357"][0] - BPFO_6309) <= 0.25 and levels["adxl357"][1] > 10
    assert abs(levels["adxl357-ds"][0] - BPFO_6309) > 1.0 and levels["adxl357-ds"][1] < 3
