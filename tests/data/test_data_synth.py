"""Synthetic pump generator: checked against vibration analysis, not against its own code."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy import signal

from sdt_framework.data import open_synthetic

FS = 20000.0
SHAFT = {"Motor-4": 0.7 * 1480 / 60, "Motor-2": 1480 / 60}  # Hz: 70 % and 100 % of 1480 rpm


def load(machine: str, run: str, channel: str, duration: float = 2.0, seed: int = 0):
    condition = run.rsplit(" ", 1)[0]
    ds = open_synthetic(seed=seed, duration=duration, machines=machine, conditions=condition)
    (rec,) = [r for r in ds.recordings() if r.run == run and r.channel == channel]
    return rec.load()[0]


def amplitude_near(x: np.ndarray, freq: float, tol: float = 0.03) -> float:
    """Peak single-sided amplitude (Hann, coherent-gain corrected) within freq*(1 +/- tol)."""
    spec = 2 * np.abs(np.fft.rfft(x * np.hanning(x.size))) / np.hanning(x.size).sum()
    f = np.fft.rfftfreq(x.size, 1 / FS)
    return float(spec[(f > freq * (1 - tol)) & (f < freq * (1 + tol))].max())


def envelope_peak(x: np.ndarray, lo: float = 20.0, hi: float = 400.0) -> float:
    """Frequency of the largest line of the envelope spectrum of the 2-8 kHz band."""
    band = signal.sosfiltfilt(signal.butter(4, [2000, 8000], "bandpass", fs=FS, output="sos"), x)
    env = np.abs(signal.hilbert(band))
    spec = np.abs(np.fft.rfft(env - env.mean()))
    f = np.fft.rfftfreq(env.size, 1 / FS)
    sel = (f >= lo) & (f <= hi)
    return float(f[sel][np.argmax(spec[sel])])


def band_energy(x: np.ndarray, lo: float = 2000.0, hi: float = 8000.0) -> float:
    f, p = signal.welch(x, fs=FS, nperseg=4096)
    return float(p[(f >= lo) & (f <= hi)].sum())


def test_default_dataset_shape_without_generating() -> None:
    ds = open_synthetic()
    recs = ds.recordings()
    runs = {(r.machine, r.run) for r in recs}
    assert sum(m == "Motor-4" for m, _ in runs) == 3 + 6 + 3 + 5 + 4 + 4 + 3 + 4 + 5
    assert sum(m == "Motor-2" for m, _ in runs) == 3 + 3 * 4
    assert len(recs) == 5 * len(runs)
    assert {r.samples_per_acquisition for r in recs} == {240000}
    assert {r.speed for r in recs} == {"70", "100"}
    assert {r.severity for r in recs if r.condition == "healthy"} == {None}


@pytest.mark.parametrize(
    ("run", "multiplier"),
    [
        ("bearing bpfo 2", 9 / 2 * (1 - 9.525 / 46.0)),  # 6206: 9 balls, d 9.525 mm, D 46 mm
        ("bearing bpfi 2", 9 / 2 * (1 + 9.525 / 46.0)),
    ],
)
def test_bearing_envelope_spectrum_peaks_at_defect_frequency(run: str, multiplier: float) -> None:
    x = load("Motor-2", run, "ch2", duration=4.0)
    expected = multiplier * SHAFT["Motor-2"]
    assert envelope_peak(x) == pytest.approx(expected, rel=0.02)


def test_unbalance_1x_rises_with_severity() -> None:
    ds = open_synthetic(
        duration=2.0, machines="Motor-4", conditions="unbalance motor", channels="ch1"
    )
    amps = [amplitude_near(r.load()[0], SHAFT["Motor-4"]) for r in ds.recordings()]
    assert len(amps) == 6 and all(b > a for a, b in itertools.pairwise(amps)), amps
    pump = open_synthetic(duration=2.0, machines="Motor-4", conditions="unbalance pump")
    by_ch = {
        r.channel: amplitude_near(r.load()[0], SHAFT["Motor-4"])
        for r in pump.recordings()
        if r.run == "unbalance pump 3"
    }
    assert by_ch["ch4"] > 2 * by_ch["ch1"]  # pump unbalance is strongest on pump bearings


def test_angular_misalignment_is_axial() -> None:
    ds = open_synthetic(duration=2.0, machines="Motor-4", conditions="align angular")
    ones = {
        (r.run, r.channel): amplitude_near(r.load()[0], SHAFT["Motor-4"]) for r in ds.recordings()
    }
    for level in range(1, 6):
        run = f"align angular {level}"
        assert ones[(run, "ch3")] > max(ones[(run, "ch1")], ones[(run, "ch2")])


def test_cavitation_band_energy_and_clipping_level() -> None:
    healthy = band_energy(load("Motor-4", "healthy 1", "ch4"))
    assert band_energy(load("Motor-4", "cavitation suction 1", "ch4")) > 20 * healthy
    assert band_energy(load("Motor-4", "cavitation discharge 1", "ch4")) > 10 * healthy
    for channel in ("ch1", "ch4"):  # beyond the ADXL345's 16 g full scale
        assert np.abs(load("Motor-4", "cavitation suction 4", channel)).max() > 16.0
    assert np.abs(load("Motor-4", "healthy 1", "ch1")).max() < 1.0


def test_seed_determinism_and_selection_independence() -> None:
    a = load("Motor-2", "impeller 2", "ch4", duration=1.0, seed=3)
    b = load("Motor-2", "impeller 2", "ch4", duration=1.0, seed=3)
    np.testing.assert_array_equal(a, b)
    assert not np.allclose(a, load("Motor-2", "impeller 2", "ch4", duration=1.0, seed=4))
    full = open_synthetic(seed=3, duration=1.0, machines="Motor-2", conditions="impeller")
    rec = next(r for r in full.recordings() if r.run == "impeller 2" and r.channel == "ch4")
    np.testing.assert_array_equal(rec.load()[0], a)


def test_channels_are_views_of_one_event() -> None:
    ds = open_synthetic(duration=1.0, machines="Motor-4", conditions="coupling")
    x = {r.channel: r.load()[0] for r in ds.recordings() if r.run == "coupling 3"}
    # the same coupling impacts reach ch2 and ch4: their envelopes are strongly correlated
    env = {
        c: np.abs(
            signal.hilbert(
                signal.sosfiltfilt(
                    signal.butter(4, [2000, 8000], "bandpass", fs=FS, output="sos"), v
                )
            )
        )
        for c, v in x.items()
    }
    assert np.corrcoef(env["ch2"], env["ch4"])[0, 1] > 0.5
    assert not np.allclose(x["ch2"], x["ch4"])
