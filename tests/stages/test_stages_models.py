"""Each built-in error stage against its analysis (variances, Allan slopes, harmonics, shifts)."""

from __future__ import annotations

import numpy as np
import pytest
from sdt_plugins.stages import clock, errors, noise

from sdt_framework.chain import RunContext
from sdt_framework.stages import StageContext
from sdt_framework.validation.allan import gauss_markov_adev
from sdt_framework.validation.allan import mean_oadev as adev

ROWS = tuple(range(4))


def build(module, name: str, params: dict, fs: float = 1000.0, target: float = 1000.0):
    spec = next(s for s in module.STAGES if s.name == name)
    context = StageContext(fs, fs, target, 2.0, f"{name}.0", "test")
    return spec.factory(spec.params.model_validate(params), context)


def run(stage, rows: int = 4, n: int = 200_000, x: np.ndarray | None = None) -> np.ndarray:
    x = np.zeros((rows, n)) if x is None else x
    return stage.apply(x, RunContext(seed=11, acquisition_ids=tuple(range(x.shape[0])), threads=1))


def slope(t: np.ndarray, d: np.ndarray) -> float:
    return float(np.polyfit(np.log(t), np.log(d), 1)[0])


def test_gauss_markov_variance_and_correlation_time():
    sigma_ug, tau_s, fs = 200.0, 0.05, 1000.0
    y = run(build(noise, "gauss-markov", {"sigma_ug": sigma_ug, "tau_s": tau_s}, fs))
    assert y.std() == pytest.approx(sigma_ug * 1e-6, rel=0.05)
    z = y - y.mean(axis=1, keepdims=True)
    lags = np.arange(1, 200)
    acf = np.array([np.mean(z[:, :-k] * z[:, k:]) for k in lags]) / np.mean(z * z)
    tau_est = lags[np.argmax(acf < np.exp(-1))] / fs  # first lag below 1/e
    assert tau_est == pytest.approx(tau_s, rel=0.1)
    # and the lag-1 correlation is exp(-dt / tau)
    assert acf[0] == pytest.approx(np.exp(-1 / (fs * tau_s)), abs=0.01)


def test_allan_slope_of_white_noise_and_vrw_value():
    vrw = 0.05  # (m/s)/sqrt(h)
    fs = 1000.0
    y = run(build(noise, "vrw", {"vrw_mps_rthr": vrw}, fs))
    taus = np.logspace(-2, 1, 10)
    t, d = adev(y, fs, taus)
    assert slope(t, d) == pytest.approx(-0.5, abs=0.05)
    n_g = vrw / 60 / 9.80665  # the ADEV at tau = 1 s (IEEE 952 Annex C)
    assert np.interp(0.0, np.log(t), np.log(d)) == pytest.approx(np.log(n_g), abs=0.1)


def test_allan_slope_of_random_walk_and_its_coefficient():
    k_ug, fs = 20.0, 100.0
    y = run(build(noise, "random-walk", {"k_ug_rts": k_ug}, fs), rows=8, n=100_000)
    taus = np.logspace(-0.3, 1, 8)  # up to 1 % of the 1000 s record: enough averages per tau
    t, d = adev(y, fs, taus)
    assert slope(t, d) == pytest.approx(0.5, abs=0.05)
    np.testing.assert_allclose(d, k_ug * 1e-6 * np.sqrt(t / 3), rtol=0.1)


def test_flicker_floor_is_0664_b():
    b_ug, fs = 50.0, 100.0
    y = run(build(noise, "flicker", {"bias_instability_ug": b_ug}, fs), rows=8, n=100_000)
    t, d = adev(y, fs, np.logspace(-1, 1.5, 8))
    expected = np.sqrt(2 * np.log(2) / np.pi) * b_ug * 1e-6
    np.testing.assert_allclose(d, expected, rtol=0.15)
    assert abs(slope(t, d)) < 0.08


def test_gauss_markov_bias_instability_floor():
    sigma_ug, tc, fs = 100.0, 0.5, 200.0
    y = run(build(noise, "gauss-markov", {"sigma_ug": sigma_ug, "tau_s": tc}, fs), n=200_000)
    taus = np.logspace(-1.5, 1.3, 12)
    t, d = adev(y, fs, taus)
    expected = gauss_markov_adev(t, sigma_ug * 1e-6, tc)
    np.testing.assert_allclose(d, expected, rtol=0.12)
    fine = np.logspace(-2, 2, 2000)
    floor = gauss_markov_adev(fine, sigma_ug * 1e-6, tc).max()
    assert d.max() == pytest.approx(floor, rel=0.1)  # the floor is read at its configured value
    assert floor / (sigma_ug * 1e-6) == pytest.approx(0.62, abs=0.01)


def test_nonlinearity_harmonics_on_a_pure_tone():
    fs, f0, amp, full = 10000.0, 100.0, 1.5, 2.0
    stage = build(errors, "nonlinearity", {"second_pct_fs": 1.0, "third_pct_fs": 0.5}, fs)
    t = np.arange(10000) / fs
    y = run(stage, x=amp * np.cos(2 * np.pi * f0 * t)[None, :])[0]
    spectrum = np.abs(np.fft.rfft(y)) * 2 / len(y)
    k2, k3 = 0.01 / full, 0.005 / full**2
    assert spectrum[200] == pytest.approx(k2 * amp**2 / 2, rel=1e-6)
    assert spectrum[300] == pytest.approx(k3 * amp**3 / 4, rel=1e-6)
    assert spectrum[100] == pytest.approx(amp + 3 * k3 * amp**3 / 4, rel=1e-6)


def crossing_frequency(y: np.ndarray, fs: float) -> float:
    i = np.flatnonzero((y[:-1] < 0) & (y[1:] >= 0))
    t = (i + y[i] / (y[i] - y[i + 1])) / fs
    return (len(t) - 1) / (t[-1] - t[0])


def test_clock_error_shifts_a_tone_and_changes_the_sample_count():
    fs, target, f0, err = 20000.0, 1000.0, 50.0, 2.0
    stage = build(clock, "clock", {"odr_error_pct": err}, fs, target)
    t = np.arange(200_000) / fs
    y = run(stage, x=np.sin(2 * np.pi * f0 * t)[None, :])[0]
    assert len(y) == int(np.floor((200_000 - 1) / fs * target * 1.02 + 1e-9)) + 1
    assert crossing_frequency(y, target) == pytest.approx(f0 / 1.02, rel=1e-5)


def test_clock_jitter_error_matches_the_slope_times_jitter():
    fs, target, f0, jitter = 20000.0, 1000.0, 100.0, 10e-6
    t = np.arange(40_000) / fs
    x = np.sin(2 * np.pi * f0 * t)[None, :].repeat(4, axis=0)
    exact = run(build(clock, "clock", {}, fs, target), x=x)
    jittered = run(build(clock, "clock", {"jitter_s": jitter}, fs, target), x=x)
    rms = np.sqrt(np.mean((jittered - exact) ** 2))
    assert rms == pytest.approx(2 * np.pi * f0 * jitter / np.sqrt(2), rel=0.05)


def test_offset_and_scale_follow_a_temperature_ramp(tmp_path):
    fs, rate = 100.0, 2.0  # deg C per second from 25 deg C
    ramp = {"kind": "ramp", "celsius": 25.0, "rate_c_per_s": rate}
    t = np.arange(500) / fs
    x = np.ones((1, 500))
    scale = build(
        errors, "scale", {"error_pct": 1, "tempco_pct_per_c": 0.02, "temperature": ramp}, fs
    )
    offset = build(
        errors, "offset", {"offset_mg": 5, "tempco_mg_per_c": 0.5, "temperature": ramp}, fs
    )
    y = run(offset, x=run(scale, x=x))[0]
    expected = (1 + 0.01 + 0.0002 * rate * t) + (0.005 + 0.0005 * rate * t)
    np.testing.assert_allclose(y, expected, rtol=0, atol=1e-12)
    csv = tmp_path / "temp.csv"
    csv.write_text("time_s,temperature_c\n0,25\n10,45\n")
    table = {"kind": "csv", "path": str(csv)}
    from_csv = build(errors, "offset", {"tempco_mg_per_c": 0.5, "temperature": table}, fs)
    from_ramp = build(errors, "offset", {"tempco_mg_per_c": 0.5, "temperature": ramp}, fs)
    np.testing.assert_allclose(run(from_csv, x=x), run(from_ramp, x=x), atol=1e-12)
