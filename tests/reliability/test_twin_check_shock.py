"""``sdt twin check`` on a real recording with shocks (issue 29 item 5).

``tests/data/endaq/Cloud_Test_000000.IDE`` (MideTechnology/endaq-python, MIT;
see the README there): an enDAQ recorder's 832M1 100 g piezo at 20 kHz
records shocks up to 144 g beside an ADXL357 (40 g) at 502 Hz. Before the
fix the check refused it ("no band can be judged": the median density over
frequency of the whole record is the shocks'). The floor and the levels are
measured here from idelib's raw arrays with scipy.signal.welch, independently
of the code under test: the floor on the quietest half second of the compared
span, the levels over the whole span.
"""

from __future__ import annotations

import json
from pathlib import Path

import idelib
import numpy as np
import pytest
from scipy import signal

FILE = Path(__file__).parents[1] / "data" / "endaq" / "Cloud_Test_000000.IDE"


#: these commands end before any worker starts: ``sdt`` runs in this process (conftest.py)
pytestmark = pytest.mark.in_process


def _raw(channel: int) -> tuple[np.ndarray, np.ndarray]:
    """(times s, values g (x, y, z)) of a channel as idelib reads it."""
    doc = idelib.importFile(str(FILE))
    try:
        raw = np.asarray(doc.channels[channel].getSession().arraySlice(), dtype=float)
    finally:
        doc.close()
    return raw[0] * 1e-6, raw[1:4]


@pytest.fixture(scope="module")
def measured() -> dict:
    """The reference's floor on its quietest half second and its band levels, from scipy."""
    t_ref, ref = _raw(8)
    t_dev, _ = _raw(80)
    start, end = max(t_ref[0], t_dev[0]) + 0.25, min(t_ref[-1], t_dev[-1]) - 0.25
    span = ref[:, (t_ref >= start) & (t_ref <= end)]
    fs = (len(t_ref) - 1) / (t_ref[-1] - t_ref[0])
    half = int(fs / 2)
    f, p = signal.welch(span, fs=fs, nperseg=4096)
    inside = (f >= 10) & (f <= 250)
    level = np.sqrt(np.median(p[:, inside], axis=1))  # g/sqrt(Hz), per axis
    floors = []
    for row in span:  # the quietest half second of each axis, by its median density
        halves = row[: len(row) // half * half].reshape(-1, half)
        fq, pq = signal.welch(halves, fs=fs, nperseg=2048, axis=-1)
        band = (fq >= 10) & (fq <= 0.4 * fs)
        medians = np.median(pq[:, band], axis=1)
        floors.append(np.sqrt(medians.min()))
    return {"floor": np.array(floors), "level": level, "peak": np.abs(span).max(axis=1)}


def test_a_shock_recording_is_judged_with_its_floor_from_quiet_seconds(sdt, measured):
    assert measured["peak"].max() > 100  # shocks beyond 100 g (144 g on y)
    run = sdt("twin", "check", str(FILE), "--sensor", "adxl357", "--json")
    assert run.returncode == 0, run.stderr
    out = json.loads(run.stdout)
    reported = np.array([f["reference_ug"] for f in out["floors"]]) * 1e-6
    # the quietest half second read by scipy, and the check's quiet segments: within 3 dB
    assert np.all(np.abs(20 * np.log10(reported / measured["floor"])) < 3.0)
    # 10-250 Hz stands more than 35 dB above that floor on every axis (the whole-record
    # median the check used before took this motion for the floor)
    assert np.all(20 * np.log10(measured["level"] / measured["floor"]) > 35)
    judged = [b for b in out["bands"] if b["judgeable"]]
    assert len(judged) >= 30
    assert {b["axis"] for b in judged} == {"x", "y", "z"}
    above = [float(b["reason"].split()[1]) for b in judged]  # "reference 47.1 dB above ..."
    assert np.median(above) > 25
    # clipping: none on the device (|a| < 40 g, counted here from idelib's samples);
    # whatever the twin clips is reported with its share and axes
    _, device = _raw(80)
    assert np.abs(device).max() < 0.999 * 40
    assert out["clipped"]["device_clipping"] == {"count": 0, "share": 0.0, "axes": {}}
    twin = out["clipped"]["twin_clipping"]
    assert twin["count"] == sum(twin["axes"].values())


def test_the_clock_error_is_read_against_the_rate_setting_the_device_runs_at(sdt):
    """An ADXL357 set to 500 Hz is a fraction of a percent off that setting, not -87 % off 4000."""
    t_dev, _ = _raw(80)
    rate = (len(t_dev) - 1) / (t_dev[-1] - t_dev[0])  # timestamps alone, as idelib gives them
    run = sdt("twin", "check", str(FILE), "--sensor", "adxl357")
    assert run.returncode == 0, run.stderr
    line = next(x for x in run.stdout.splitlines() if x.startswith("alignment:"))
    assert "from the 500 Hz setting of 4000" in line
    printed = float(line.split("(")[1].split(" %")[0])
    assert abs(printed - 100 * (rate / 500 - 1)) < 0.1
