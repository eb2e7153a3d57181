"""``sdt twin check`` on broadband and clipping pairs whose floor is known (issue 29 item 5).

The reference (20 kHz, 8 s) is white noise of :data:`N_REF` g/sqrt(Hz) on every
axis, plus band-limited random motion of :data:`S_MOTION` g^2/Hz (10-2500 Hz)
from 4 s on: the first seconds are quiet. The device is the reference
resampled to 3200 Hz (scipy's polyphase filter) plus white noise of
:data:`N_DEV` g/sqrt(Hz) and gravity on z; in the clipping pair the reference
also carries three 60 g shocks on x and the device is clipped at the
ADXL345's 16 g. Floors, levels and clipped samples are computed here from
these numbers and arrays, not by the code under test. Before the fix the
check refused both pairs ("no band can be judged"): the median density over
frequency of a broadband record is the motion, not the floor.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy import signal

FS_REF, FS_DEV, SECONDS, MOTION_FROM_S = 20_000, 3200, 8.0, 4.0
N_REF = 50e-6  # reference floor, g/sqrt(Hz)
N_DEV = 290e-6  # device noise, g/sqrt(Hz) (the ADXL345's datasheet density)
S_MOTION = (2e-3) ** 2  # motion PSD, g^2/Hz, 10-2500 Hz


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


FULL_SCALE = 16.0  # adxl345


def _white(rng: np.random.Generator, density: float, fs: float, n: int) -> np.ndarray:
    """Three rows of white noise of one-sided density ``density`` (g/sqrt(Hz))."""
    return density * np.sqrt(fs / 2) * rng.normal(size=(3, n))


def _pair(folder, shocks: bool) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(29)
    n = int(SECONDS * FS_REF)
    t = np.arange(n) / FS_REF
    spectrum = np.fft.rfft(_white(rng, np.sqrt(S_MOTION), FS_REF, n), axis=1)
    f = np.fft.rfftfreq(n, 1 / FS_REF)
    motion = np.fft.irfft(spectrum * ((f >= 10) & (f <= 2500)), n, axis=1)
    reference = _white(rng, N_REF, FS_REF, n) + motion * (t >= MOTION_FROM_S)
    if shocks:  # 2 ms half-sines of 60 g on x
        for at in (5.0, 6.0, 7.0):
            inside = (t >= at) & (t < at + 2e-3)
            reference[0, inside] += 60 * np.sin(np.pi * (t[inside] - at) / 2e-3)
    device = signal.resample_poly(reference, 4, 25, axis=1)  # 20000 * 4 / 25 = 3200
    device += _white(rng, N_DEV, FS_DEV, device.shape[1])
    device[2] += 1.0  # gravity: the device is DC-coupled
    if shocks:
        device = np.clip(device, -FULL_SCALE, FULL_SCALE)
    np.save(folder / "ref.npy", reference)
    np.save(folder / "dev.npy", device)
    (folder / "pair.toml").write_text(
        f'[reference]\nfile = "ref.npy"\naxes = ["x", "y", "z"]\nrate_hz = {FS_REF}\n\n'
        f'[device]\nfile = "dev.npy"\naxes = ["x", "y", "z"]\nrate_hz = {FS_DEV}\n'
    )
    return reference, device


def _check(sdt, folder) -> dict:
    run = sdt("twin", "check", str(folder / "pair.toml"), "--sensor", "adxl345", "--json")
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout)


def test_a_broadband_pair_is_judged_against_the_floor_of_its_quiet_seconds(sdt, tmp_path):
    _pair(tmp_path, shocks=False)
    out = _check(sdt, tmp_path)
    for floor in out["floors"]:  # the reference's white floor, 50 ug/sqrt(Hz), within 0.5 dB
        assert 20 * np.log10(floor["reference_ug"] / (1e6 * N_REF)) == pytest.approx(0, abs=0.5)
        # the device's: its own noise and the reference's, added in power
        expected = 1e6 * np.hypot(N_DEV, N_REF)
        assert 20 * np.log10(floor["device_ug"] / expected) == pytest.approx(0, abs=0.5)
    # every band of every axis (10 Hz to the device's Nyquist) carries motion over the
    # half of the compared span after 4 s: band power (S * share + N^2) * width over a
    # floor N^2 * width
    start = 0.25  # the check's margin at the start of the overlap
    share = (start + out["pair"]["overlap_s"] - MOTION_FROM_S) / out["pair"]["overlap_s"]
    expected_db = 10 * np.log10((S_MOTION * share + N_REF**2) / N_REF**2)
    bands = out["bands"]
    assert all(b["judgeable"] for b in bands), [b["reason"] for b in bands if not b["judgeable"]]
    assert out["summary"]["judgeable_bands"] == len(bands) >= 3 * 20
    above = np.array([float(b["reason"].split()[1]) for b in bands])  # "reference 28.9 dB ..."
    assert np.median(above) == pytest.approx(expected_db, abs=1.0)
    assert np.all(np.abs(above - expected_db) < 3.0)


def test_b_a_clipping_device_is_judged_and_its_clipping_reported(sdt, tmp_path):
    _, device = _pair(tmp_path, shocks=True)
    out = _check(sdt, tmp_path)
    assert out["summary"]["judgeable_bands"] > 0
    clipped = out["clipped"]["device_clipping"]
    # every clipped sample lies at 5-7 s, inside the compared span: counted over the array
    per_axis = np.count_nonzero(np.abs(device) >= 0.999 * FULL_SCALE, axis=1)
    assert per_axis[0] > 0 and per_axis[1:].sum() == 0
    assert clipped["count"] == out["clipped"]["device"] == per_axis.sum()
    assert clipped["axes"] == {"x": int(per_axis[0])}
    compared = round(out["pair"]["overlap_s"] * out["pair"]["device"]["rate_hz"])
    assert clipped["share"] == pytest.approx(per_axis.sum() / (3 * compared), rel=1e-3)
    assert "x" in out["clipped"]["twin_clipping"]["axes"]  # the twin of a 16 g part clips too


def test_text_output_names_the_clipped_share_and_axes(sdt, tmp_path):
    _, device = _pair(tmp_path, shocks=True)
    run = sdt("twin", "check", str(tmp_path / "pair.toml"), "--sensor", "adxl345")
    assert run.returncode == 0, run.stderr
    count = int(np.count_nonzero(np.abs(device) >= 0.999 * FULL_SCALE))
    assert f"samples at full scale: device {count} (" in run.stdout
    assert f"; x {count})" in run.stdout
