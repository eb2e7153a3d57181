"""What ``sdt twin check`` concludes, and why it refuses, named by the real cause (issue 29:
B2 and the weak twin-check items).

- At rest (no coherent tone) no gain is measured: the check must say so, not
  that the device "agrees with the reference in gain".
- A device channel checked as a part it is not (an ADXL345 at 3134 Hz as an
  IIS3DWB, 26667 Hz, +-2 g) must be named as a rate mismatch and a clipping
  twin, not as "the reference's gain disagreement".
- A pair whose device rate is 1000 times too low (timestamps in ms, a
  ``rate_hz`` off 1000-fold) must be refused naming the rate, not as "a
  recording at rest?".

Rates, peaks and spreads are computed here from idelib's raw arrays.
"""

from __future__ import annotations

import json
from pathlib import Path

import idelib
import numpy as np
import pytest

DATA = Path(__file__).parents[1] / "data" / "endaq"


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _raw(name: str, channel: int) -> tuple[np.ndarray, np.ndarray]:
    doc = idelib.importFile(str(DATA / name))
    try:
        raw = np.asarray(doc.channels[channel].getSession().arraySlice(), dtype=float)
    finally:
        doc.close()
    return raw[0] * 1e-6, raw[1:4]


@pytest.mark.parametrize(
    ("name", "sensor", "device"),
    [("SSX_Data.IDE", "adxl345", 32), ("XS5E25D40.IDE", "adxl357", 80)],
)
def test_at_rest_no_gain_is_compared_and_none_is_claimed(sdt, name, sensor, device):
    # independent: both parts are at rest (spread under 50 mg, against 3.5 g of tone in
    # SSX66115): there is no motion whose gain the pair could read
    for channel in (8, device):
        _, values = _raw(name, channel)
        assert values.std(axis=1).max() < 0.05
    run = sdt("twin", "check", str(DATA / name), "--sensor", sensor)
    assert run.returncode == 0, run.stderr
    line = next(x for x in run.stdout.splitlines() if x.startswith("calibration:"))
    assert "agrees with the reference in gain" not in line
    assert "no gain could be compared" in line
    assert "device/twin gain" not in line  # no gain printed: none was measured


def test_a_part_checked_at_another_parts_rate_names_the_rate_and_the_clipping(sdt):
    t, dev = _raw("SSX66115.IDE", 32)
    rate = (len(t) - 1) / (t[-1] - t[0])  # the ADXL345's 3134 Hz
    run = sdt("twin", "check", str(DATA / "SSX66115.IDE"), "--sensor", "iis3dwb",
              "--device-channel", "32", "--json")  # fmt: skip
    assert run.returncode == 0, run.stderr
    out = json.loads(run.stdout)
    line = out["calibration"]["verdict"]  # the text output's calibration line ends with it
    assert "the reference's" not in line
    assert f"runs at {rate:.4g} Hz, {26667 / rate:.3g} times slower than iis3dwb" in line
    assert "the twin clips (" in line and "at +-2 g" in line
    assert f"reads up to {np.abs(dev).max():.3g} g, beyond" in line  # an 11 g tone on x
    assert out["calibration"]["reference_off"] is False  # `twin fit` writes no reference fix
    assert out["clipped"]["twin"] > 0


@pytest.mark.parametrize("form", ["rate_hz", "milliseconds"])
def test_a_device_rate_1000_times_too_low_is_named_not_taken_for_rest(sdt, tmp_path, form):
    t_ref = np.arange(5 * 5000) / 5000
    t_dev = np.arange(5 * 3200) / 3200
    np.save(tmp_path / "ref.npy", np.sin(2 * np.pi * 100 * t_ref)[None])
    device = np.sin(2 * np.pi * 100 * t_dev)
    if form == "rate_hz":
        np.save(tmp_path / "dev.npy", device[None])
        side = 'file = "dev.npy"\nrate_hz = 3.2\n'
    else:  # the time column in milliseconds, read as seconds
        rows = "\n".join(f"{1e3 * a:.6f},{b:.9f}" for a, b in zip(t_dev, device, strict=True))
        (tmp_path / "dev.csv").write_text("t,ax\n" + rows + "\n")
        side = 'file = "dev.csv"\ncolumns = ["ax"]\ntime_column = "t"\n'
    (tmp_path / "pair.toml").write_text(
        '[reference]\nfile = "ref.npy"\naxes = ["x"]\nrate_hz = 5000\n\n'
        f'[device]\n{side}axes = ["x"]\n'
    )
    run = sdt("twin", "check", str(tmp_path / "pair.toml"), "--sensor", "adxl345")
    assert run.returncode == 2
    assert run.stderr.count("\n") == 1 and "Traceback" not in run.stderr
    assert "at rest" not in run.stderr.replace("not a recording at rest", "")
    # the pair's own validation names it before any check: 5 s of reference, 5000 s of device
    assert "two sides differ 1000-fold in length" in run.stderr
    assert "a time column in ms or a rate_hz in kHz?" in run.stderr
