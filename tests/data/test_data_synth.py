"""Synthetic pump generator: checked against vibration analysis, not against its own code.

Physics tests that need the shaft-synchronous model alone switch the run-to-run
scatter off (``no_scatter``); the scatter itself is checked against the spread
it must reproduce (docs/data.md, "Calibration").
"""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest
from scipy import signal
from sdt_plugins.datasets.synthetic_pump import dataset as synth_dataset
from sdt_plugins.datasets.synthetic_pump import faults as faults
from sdt_plugins.datasets.synthetic_pump import model as model
from sdt_plugins.datasets.synthetic_pump import open_synthetic
from sdt_plugins.datasets.synthetic_pump.generate import generate_run

from sdt_framework.api import degrade
from sdt_framework.errors import SDTError
from sdt_framework.registry import build_registry

from .synth_common import amplitude_near

FS = 20000.0
# Motor-4 at 70 % runs at 2075 rpm (2-pole motor); Motor-2 at 100 % at 1480 rpm
SHAFT = {"Motor-4": 2075 / 60, "Motor-2": 1480 / 60}


def load(machine: str, run: str, channel: str, duration: float = 2.0, seed: int = 0):
    condition = run.rsplit(" ", 1)[0]
    ds = open_synthetic(seed=seed, duration=duration, machines=machine, conditions=condition)
    (rec,) = [r for r in ds.recordings() if r.run == run and r.channel == channel]
    return rec.load()[0]


def gen(machine: str, condition: str, level: int, channels, duration=1.0, seed=0, acq=1):
    return generate_run(
        machine,
        condition,
        level,
        channels=tuple(channels),
        acquisitions=acq,
        duration_s=duration,
        seed=seed,
    )


def envelope_spectrum(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Spectrum of the Hilbert envelope of the 2-8 kHz band."""
    band = signal.sosfiltfilt(signal.butter(4, [2000, 8000], "bandpass", fs=FS, output="sos"), x)
    env = np.abs(signal.hilbert(band))
    return np.fft.rfftfreq(env.size, 1 / FS), np.abs(np.fft.rfft(env - env.mean()))


def band_rms(x: np.ndarray, lo: float, hi: float) -> float:
    f, p = signal.welch(x, fs=FS, nperseg=4096)
    sel = (f >= lo) & (f < hi)
    return float(np.sqrt(np.trapezoid(p[sel], f[sel])))


def test_default_dataset_shape_without_generating() -> None:
    ds = open_synthetic()
    recs = ds.recordings()
    runs = {(r.machine, r.run) for r in recs}
    # cavitation suction has levels 1, 3 and 4: the real archive holds no Motor-4 level 2
    assert sum(m == "Motor-4" for m, _ in runs) == 3 + 6 + 3 + 5 + 4 + 4 + 3 + 3 + 5
    assert ("Motor-4", "cavitation suction 2") not in runs
    assert sum(m == "Motor-2" for m, _ in runs) == 3 + 3 * 4
    assert len(recs) == 5 * len(runs)
    assert {r.samples_per_acquisition for r in recs} == {240000}
    assert {r.speed for r in recs} == {"70", "100"}
    assert {r.severity for r in recs if r.condition == "healthy"} == {None}


@pytest.mark.parametrize("machine", ["Motor-4", "Motor-2"])
def test_largest_low_frequency_line_is_the_rig_running_speed(machine: str) -> None:
    x = load(machine, "healthy 1", "ch1", duration=4.0)
    f = np.fft.rfftfreq(x.size, 1 / FS)
    spec = np.abs(np.fft.rfft(x * np.hanning(x.size)))
    sel = (f > 5) & (f < 1.5 * SHAFT[machine])
    assert f[sel][np.argmax(spec[sel])] == pytest.approx(SHAFT[machine], rel=0.01)


# motor bearing 6309: 8 balls of 17.46 mm on a 72.5 mm pitch circle (bore 45, OD 100 mm)
@pytest.mark.parametrize(
    ("run", "multiplier"),
    [
        ("bearing bpfo 1", 8 / 2 * (1 - 17.46 / 72.5)),
        ("bearing bpfo 3", 8 / 2 * (1 - 17.46 / 72.5)),
        ("bearing bpfi 1", 8 / 2 * (1 + 17.46 / 72.5)),
        ("bearing bpfi 3", 8 / 2 * (1 + 17.46 / 72.5)),
    ],
)
def test_bearing_envelope_spectrum_peaks_at_defect_frequency(run: str, multiplier: float) -> None:
    # seeded defects: present from level 1, though the real ch2 kurtosis stays below 3
    f, spec = envelope_spectrum(load("Motor-2", run, "ch2", duration=4.0))
    expected = multiplier * SHAFT["Motor-2"]
    sel = (f >= 20) & (f <= 400)
    if run.endswith("3"):  # the strongest defect: the envelope's largest line
        assert f[sel][np.argmax(spec[sel])] == pytest.approx(expected, rel=0.02)
    line = spec[(f > expected * 0.98) & (f < expected * 1.02)].max()
    assert line > 10 * np.median(spec[sel])  # a clear line above the flow-noise floor


@pytest.mark.usefixtures("no_scatter")
def test_unbalance_1x_is_the_vector_sum_of_residual_and_added_unbalance() -> None:
    # |R + s F|^2 = |R|^2 + 2 s Re(R F*) + s^2 |F|^2: exactly quadratic in the added
    # unbalance s (the model's effective size of each level; s = 0: the healthy run,
    # the same residual once the scatter is off)
    f1 = SHAFT["Motor-4"]
    amps = [amplitude_near(gen("Motor-4", "healthy", 1, ["ch2"], 2.0)["ch2"][0], f1)]
    amps += [
        amplitude_near(gen("Motor-4", "unbalance motor", k, ["ch2"], 2.0)["ch2"][0], f1)
        for k in range(1, 7)
    ]
    power = np.square(amps)
    size = np.array([0.0, *faults.SEVERITY_STEPS["unbalance motor"]])
    coef, residual, *_ = np.polyfit(size, power, 2, full=True)
    assert coef[0] > 0
    assert residual[0] < 1e-3 * np.sum((power - power.mean()) ** 2)  # R^2 > 0.999
    assert amps[6] > 2 * amps[1]
    # a large added unbalance on the pump is seen mostly at the pump bearings
    big = gen("Motor-4", "unbalance pump", 40, ["ch1", "ch4", "ch5"])
    one = {ch: amplitude_near(v[0], f1) for ch, v in big.items()}
    assert min(one["ch4"], one["ch5"]) > 2 * one["ch1"]


@pytest.mark.usefixtures("no_scatter")
def test_angular_misalignment_grows_most_in_the_axial_direction() -> None:
    f1 = SHAFT["Motor-4"]
    chans = ["ch1", "ch2", "ch3"]
    healthy = gen("Motor-4", "healthy", 1, chans, 2.0)
    angular = gen("Motor-4", "align angular", 5, chans, 2.0)
    growth = {
        c: amplitude_near(angular[c][0], f1) / amplitude_near(healthy[c][0], f1) for c in chans
    }
    assert growth["ch3"] > 1.5 * max(growth["ch1"], growth["ch2"])


def test_cavitation_suction_stays_far_inside_the_mems_ranges_and_marks_the_pump() -> None:
    """The real archive (column0_stats.csv): cavitation suction 4 peaks at 2.0 g on ch1,
    4.7 g on ch4, so no MEMS sensor of the paper clips; suction raises the pump channels'
    kHz band (real ch4 RMS 1.04 g at level 1 against 0.30-0.39 g healthy), not ch1's."""
    x = load("Motor-4", "cavitation suction 4", "ch1", duration=12.0)
    registry = build_registry()
    y345, _ = degrade(x, FS, registry.sensor("adxl345"), noise=False)
    assert np.abs(y345).max() < 16.0 - 1e-9
    assert 1.0 < np.abs(x).max() < 4.0  # within 2x of the real 2.0 g
    healthy = {ch: load("Motor-4", "healthy 1", ch) for ch in ("ch1", "ch4")}
    suction = {ch: load("Motor-4", "cavitation suction 1", ch) for ch in ("ch1", "ch4")}
    assert band_rms(suction["ch4"], 1000, 8000) > 2 * band_rms(healthy["ch4"], 1000, 8000)
    assert band_rms(suction["ch1"], 1000, 8000) < 1.5 * band_rms(healthy["ch1"], 1000, 8000)


def test_run_to_run_scatter_matches_the_calibration() -> None:
    """Healthy runs differ as in the real rig: ch2's low band by tens of percent, ch5's
    by a few; acquisitions within a run by a few percent."""
    logs = {"ch2": [], "ch5": []}
    for seed in range(6):
        for k in (1, 2, 3):
            run = gen("Motor-4", "healthy", k, ["ch2", "ch5"], seed=seed)
            for ch in logs:
                logs[ch].append(np.log(band_rms(run[ch][0], 10, 200)))
    sd = {ch: np.std(v, ddof=1) for ch, v in logs.items()}
    assert 0.25 < sd["ch2"] < 0.9
    assert sd["ch5"] < 0.5 * sd["ch2"]
    acq = gen("Motor-4", "healthy", 1, ["ch5"], acq=6)["ch5"]
    rms = [band_rms(a, 10, 200) for a in acq]
    assert 0.005 < np.std(rms, ddof=1) / np.mean(rms) < 0.1


def test_seed_determinism_and_selection_independence() -> None:
    a = load("Motor-2", "impeller 2", "ch4", duration=1.0, seed=3)
    b = load("Motor-2", "impeller 2", "ch4", duration=1.0, seed=3)
    np.testing.assert_array_equal(a, b)
    assert not np.allclose(a, load("Motor-2", "impeller 2", "ch4", duration=1.0, seed=4))
    full = open_synthetic(seed=3, duration=1.0, machines="Motor-2", conditions="impeller")
    rec = next(r for r in full.recordings() if r.run == "impeller 2" and r.channel == "ch4")
    np.testing.assert_array_equal(rec.load()[0], a)


def test_recordings_name_the_generator_so_old_cached_features_are_not_reused() -> None:
    here = Path(synth_dataset.__file__).parent
    # every module and data file of the package (the model, the code that draws, the marks
    # of each speed, the speeds' laws) and the rig's speeds and bearings it reads
    files = sorted(p.name for p in here.iterdir() if p.suffix in (".py", ".toml"))
    for needed in ("generate.py", "sources.py", "mix.py", "speeds.py", "marks.toml",
                   "marks_motor2_50.toml", "speeds.toml", "model.py", "faults.py"):  # fmt: skip
        assert needed in files
    digest = hashlib.sha256(
        b"".join((here / n).read_bytes() for n in [*files, "../pump_rig.toml"])
    ).hexdigest()[:12]
    (rec, *_) = open_synthetic(machines="Motor-2").recordings()
    assert rec.metadata()["source"] == f"synthetic (generator {digest})"


def test_channels_are_views_of_one_event() -> None:
    x = gen("Motor-4", "cavitation suction", 1, ["ch4", "ch5"])
    # the same cavitation bursts reach both pump channels (the real ones carry them: kurtosis
    # 5.3 and 6.3 at level 1): their envelopes are correlated
    bp = signal.butter(4, [2000, 8000], "bandpass", fs=FS, output="sos")
    env = {c: np.abs(signal.hilbert(signal.sosfiltfilt(bp, v[0]))) for c, v in x.items()}
    assert np.corrcoef(env["ch4"], env["ch5"])[0, 1] > 0.3
    assert not np.allclose(x["ch4"], x["ch5"])


def test_real_layout_holds_the_archive_columns_in_60_s_acquisitions() -> None:
    """The data article: healthy runs 60 columns of 12 s (12 acquisitions of 60 s),
    fault runs 10-20 (2-4 acquisitions); five consecutive columns are one acquisition."""
    ds = open_synthetic(layout="real", machines="Motor-4", conditions=["healthy", "coupling"])
    recs = ds.recordings()
    assert {(r.condition, r.n_acquisitions) for r in recs} == {("healthy", 60), ("coupling", 15)}
    healthy = next(r for r in recs if r.condition == "healthy")
    assert len(set(healthy.measurement)) == 12
    assert healthy.measurement[:6] == (0, 0, 0, 0, 0, 1)
    with pytest.raises(SDTError, match="layout"):
        open_synthetic(layout="archive")
