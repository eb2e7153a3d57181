"""Allan read-off of ``validate-noise`` against analysis: N, VRW, bias instability, NaN reasons."""

from __future__ import annotations

import math

import numpy as np
import pytest
from sdt_plugins.stages import noise

from sdt_framework.chain import RunContext
from sdt_framework.specs import SensorSpec
from sdt_framework.specs.stage_use import StageUse
from sdt_framework.stages import StageContext
from sdt_framework.validation import noise_check
from sdt_framework.validation.allan import allan_curve, gauss_markov_adev
from sdt_framework.validation.allan_check import allan_check, configured_terms

G0 = 9.80665


def stage_output(name: str, params: dict, fs: float, n: int, seed: int = 5) -> np.ndarray:
    """One record of a built-in noise stage alone, on a zero input."""
    spec = next(s for s in noise.STAGES if s.name == name)
    stage = spec.factory(
        spec.params.model_validate(params), StageContext(fs, fs, fs, 2.0, "t", "t")
    )
    return stage.apply(np.zeros((1, n)), RunContext(seed=seed, acquisition_ids=(0,), threads=1))[0]


def bare(**fields) -> SensorSpec:
    """A profile without filters or quantisation: its output is its noise terms alone."""
    base = dict(name="bare", sampling_rate_hz=1000, full_scale_g=None, adc_bits=None)
    base |= dict(requantise=False, mech_cutoff_hz=None, analog_cutoff_hz=None)
    return SensorSpec(**{"noise_density_ug_rthz": 0.0, **base, **fields})


def test_white_noise_of_one_sided_psd_s0_has_adev_sqrt_s0_over_2_tau() -> None:
    """The sqrt(2): allantools' own PSD -> ADEV transform (NIST SP 1065 eq. 65) of a flat PSD."""
    import allantools

    s0, df = 4.0e-8, 0.01  # one-sided, g^2/Hz
    taus, dev = allantools.psd2allan(np.full(200_000, s0), df, kind="adev")
    mid = (taus > 0.5) & (taus < 20)
    np.testing.assert_allclose(dev[mid], np.sqrt(s0 / (2 * taus[mid])), rtol=0.01)


def test_white_noise_reads_its_density_and_vrw() -> None:
    nsd_ug, fs = 250.0, 1000.0
    x = np.random.default_rng(3).normal(0.0, nsd_ug * 1e-6 * math.sqrt(fs / 2), 400_000)
    curve = allan_curve(x, fs)
    assert curve.n_g * math.sqrt(2) * 1e6 == pytest.approx(nsd_ug, rel=0.02)
    # VRW of 250 ug/sqrt(Hz): 250e-6 / sqrt(2) x 9.80665 m/s^2 x 60 sqrt(s)/sqrt(h)
    assert curve.to_dict()["vrw_mps_rthr"] == pytest.approx(0.104017, rel=0.03)
    assert math.isnan(curve.b_g) and "no flat region" in curve.b_reason
    assert curve.taus[-1] == pytest.approx(400_000 / 20 / fs)  # a twentieth of the record


def test_configured_white_terms_add_in_power_and_convert_vrw() -> None:
    profile = bare(
        noise_density_ug_rthz=300,
        stages=(
            StageUse(name="white-noise", params={"density_ug_rthz": 400}),
            StageUse(name="vrw", params={"vrw_mps_rthr": 0.05}),
        ),
    )
    cfg = configured_terms(profile)
    vrw_nsd = 0.05 / 60 / G0 * math.sqrt(2)  # the vrw stage as a one-sided density
    assert cfg.nsd_g == pytest.approx(math.sqrt(300e-6**2 + 400e-6**2 + vrw_nsd**2))
    assert cfg.b_g is None and cfg.to_dict()["bias_instability_ug"] is None
    assert configured_terms(bare()).nsd_g is None


def test_gauss_markov_closed_form_has_the_textbook_limits() -> None:
    sigma, tc = 1.0, 2.0
    short, long_ = np.array([1e-4, 1e-3]), np.array([1e3, 1e4])
    np.testing.assert_allclose(
        gauss_markov_adev(short, sigma, tc), sigma * np.sqrt(2 * short / (3 * tc)), rtol=1e-3
    )
    np.testing.assert_allclose(
        gauss_markov_adev(long_, sigma, tc), sigma * np.sqrt(2 * tc / long_), rtol=2e-3
    )


def test_gauss_markov_alone_reads_its_configured_bias_instability() -> None:
    sigma_ug, tc, fs = 100.0, 0.5, 200.0
    cfg = configured_terms(
        bare(
            sampling_rate_hz=fs,
            stages=(StageUse(name="gauss-markov", params={"sigma_ug": sigma_ug, "tau_s": tc}),),
        )
    )
    assert cfg.b_g / (sigma_ug * 1e-6) == pytest.approx(0.618 / 0.664, abs=0.01)  # hump 0.618 sigma
    for seed in (1, 2):
        curve = allan_curve(
            stage_output("gauss-markov", {"sigma_ug": sigma_ug, "tau_s": tc}, fs, 200_000, seed), fs
        )
        assert curve.b_g == pytest.approx(cfg.b_g, rel=0.1)
        assert curve.floor_tau == pytest.approx(1.89 * tc, rel=0.5)  # at the hump


def test_flicker_alone_reads_b_and_its_floor_is_0664_b() -> None:
    b_ug, fs = 50.0, 100.0
    curve = allan_curve(stage_output("flicker", {"bias_instability_ug": b_ug}, fs, 100_000), fs)
    assert curve.b_g * 1e6 == pytest.approx(b_ug, rel=0.1)
    assert curve.floor_g * 1e6 == pytest.approx(0.664 * b_ug, rel=0.1)  # IEEE 952 floor


def test_curves_without_a_minimum_or_a_white_region_give_nan_and_the_reason() -> None:
    fs = 200.0
    # white 100 ug/sqrt(Hz) over a 1/f floor of 6.6 ug: they cross at 113 s, beyond the taus
    white = stage_output("white-noise", {"density_ug_rthz": 100}, fs, 200_000, seed=7)
    curve = allan_curve(
        white + stage_output("flicker", {"bias_instability_ug": 10}, fs, 200_000), fs
    )
    assert math.isfinite(curve.n_g) and math.isnan(curve.b_g)
    assert curve.b_reason.startswith("no flat region (slope 0 +- 0.1): for tau 0.02-15.8 s")
    walk = allan_curve(stage_output("random-walk", {"k_ug_rts": 10}, fs, 200_000), fs)
    assert math.isnan(walk.n_g) and walk.n_reason.startswith("no slope -1/2 region")
    assert walk.to_dict()["n_ug_rthz"] is None and walk.to_dict()["white_reason"]
    silent = allan_curve(np.zeros(5000), fs)
    assert math.isnan(silent.n_g) and "does not vary" in silent.b_reason
    short = allan_curve(np.random.default_rng(0).normal(size=40), fs)
    assert short.n_reason == "40 samples give 2 tau(s); need 3: a longer record"


def test_band_limited_chain_reads_n_and_no_floor(adxl357: SensorSpec) -> None:
    check = noise_check(adxl357, n_windows=16)
    allan = allan_check(check, adxl357)
    assert allan.sdt.n_g * math.sqrt(2) * 1e6 == pytest.approx(90.0, rel=0.04)
    assert allan.configured.nsd_g * 1e6 == pytest.approx(90.0)
    assert "beyond the sensor's bandwidth" in allan.sdt.b_reason  # its filters, not a floor
    assert allan.sdt.samples == 16 * 2048 and allan.recording is None
    data = allan.to_dict()
    assert data["configured"]["bias_instability_ug"] is None and "recording" not in data


def test_recording_gets_its_own_curve(adxl345: SensorSpec) -> None:
    rec = np.random.default_rng(2).normal(0.0, 290e-6 * math.sqrt(1600), 40_000)
    check = noise_check(adxl345, recording=rec, recording_fs=3200)
    allan = allan_check(check, adxl345)
    assert allan.recording is not None and allan.recording.samples == 40_000  # all of it
    assert allan.recording.n_g * math.sqrt(2) * 1e6 == pytest.approx(290.0, rel=0.04)
    assert allan.to_dict()["recording"]["tau_range_s"][1] == pytest.approx(40_000 / 20 / 3200)
