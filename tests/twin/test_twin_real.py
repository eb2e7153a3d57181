"""The IDE reader and ``sdt twin`` on the four real enDAQ recordings (tests/data/endaq).

Rates and band levels are recomputed here from idelib's raw arrays, independently
of the code under test.
"""

from __future__ import annotations

from pathlib import Path

import idelib
import numpy as np
import pytest
from sdt_plugins.readers.ide.parse import inspect_ide, read_ide

from sdt_framework.twin import check_twin, load_pair

DATA = Path(__file__).parents[1] / "data" / "endaq"
PARTS = {
    "SSX66115.IDE": (32, "ADXL345"),
    "SSX_Data.IDE": (32, "ADXL345"),
    "DAQ12006_000005.IDE": (80, "ADXL357"),
    "XS5E25D40.IDE": (80, "ADXL357"),
}


def _raw(name: str, channel: int) -> np.ndarray:
    doc = idelib.importFile(str(DATA / name))
    try:
        return np.asarray(doc.channels[channel].getSession().arraySlice(), dtype=float)
    finally:
        doc.close()


@pytest.mark.parametrize("name", sorted(PARTS))
def test_channels_parts_and_measured_rates(name):
    channels = {c.id: c for c in inspect_ide(DATA / name)}
    device, part = PARTS[name]
    assert any(p.startswith("832M1") for p in channels[8].parts)
    assert any(p.startswith(part) for p in channels[device].parts)
    for cid in (8, device):
        t = _raw(name, cid)[0] * 1e-6
        overall = (len(t) - 1) / (t[-1] - t[0])  # first to last timestamp
        design = np.stack([np.arange(len(t)), np.ones(len(t))], axis=1)
        (period, _), *_ = np.linalg.lstsq(design, t, rcond=None)  # least-squares line
        assert channels[cid].rate_hz == pytest.approx(1 / period, rel=1e-9)
        assert channels[cid].rate_hz == pytest.approx(overall, rel=1e-3)
    assert channels[8].rate_hz == pytest.approx(5000, rel=0.001)
    nominal = 3200 if part == "ADXL345" else 4000
    assert 0.97 < channels[device].rate_hz / nominal < 1.02  # a few % off nominal, as measured


def test_values_are_in_g_and_uneven_timestamps_are_resampled_with_a_note():
    rest = read_ide(DATA / "SSX_Data.IDE", 32, ["x"])
    assert rest.values[0].mean() == pytest.approx(1.0, abs=0.02)  # gravity on X, at rest
    assert rest.note is None  # even within a sample period: used as recorded
    moved = read_ide(DATA / "DAQ12006_000005.IDE", 80, ["y"])
    assert moved.note and "resampled" in moved.note


def test_check_reports_the_real_devices_band_rms(registry, readers):
    pair = load_pair(DATA / "SSX66115.IDE", "adxl345", readers=readers)
    result = check_twin(pair, registry.sensor("adxl345"))
    assert result.summary.judgeable_bands >= 8
    # independent: the device's raw samples over the compared span, and Welch's estimate
    # written out with numpy (Hann segments of 2^round(log2 fs) samples, half overlap,
    # each segment's mean removed, density scaling), band power summed
    raw = _raw("SSX66115.IDE", 32)
    t = raw[0] * 1e-6
    fs = result.pair.device.rate_hz
    n = round(result.pair.overlap_s * fs)
    ref_t = _raw("SSX66115.IDE", 8)[0] * 1e-6
    first = int(np.searchsorted(t, max(t[0], ref_t[0]) + 0.25))
    span = raw[1:, first : first + n]
    size = 2 ** round(np.log2(fs))
    window = 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(size) / size)  # periodic Hann
    starts = range(0, n - size + 1, size // 2)
    segments = np.stack([span[:, s : s + size] for s in starts], axis=1)
    segments = segments - segments.mean(axis=-1, keepdims=True)
    power = np.abs(np.fft.rfft(segments * window, axis=-1)) ** 2
    density = power.mean(axis=1) * 2 / (fs * (window**2).sum())
    f = np.fft.rfftfreq(size, 1 / fs)
    axes = {"x": 0, "y": 1, "z": 2}
    for band in (b for b in result.bands if b.judgeable):
        inside = (f >= band.f_lower_hz) & (f < band.f_upper_hz)
        expected = np.sqrt(density[axes[band.axis], inside].sum() * (f[1] - f[0]))
        assert band.real_rms_g == pytest.approx(expected, rel=0.01), band


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["twin", "check", "{data}/LICENSE", "--sensor", "adxl345"],
         "not a recorder file of channels (enDAQ IDE: .ide) nor a pair file"),
        (["twin", "check", "{data}/SSX66115.IDE", "--sensor", "adxl345", "--axes", "w"],
         "axis 'w' is not on both channels"),
        (["twin", "check", "{data}/SSX66115.IDE", "--sensor", "adxl345",
          "--device-channel", "99"], "no acceleration channel 99"),
        (["twin", "check", "{data}/SSX_Data.IDE", "--sensor", "adxl357"], "none of the"),
        (["twin", "fit", "{data}/SSX_Data.IDE", "--sensor", "wilcoxon-786b10",
          "--device-channel", "32", "--out", "{tmp}/w.toml"], "cannot be fitted"),
        (["twin", "fit", "{data}/SSX66115.IDE", "--sensor", "adxl345", "--out", "{tmp}/f.txt"],
         "unsupported extension '.txt'; use one of .toml"),
        (["twin", "fit", "{data}/SSX66115.IDE", "--sensor", "adxl345", "--out",
          "{data}/SSX_Data.IDE"], "unsupported extension '.ide'"),
    ],
)  # fmt: skip
def test_bad_input_is_one_line(sdt_main, tmp_path, args, words):
    code, _, err = sdt_main(*[a.format(data=DATA, tmp=tmp_path) for a in args])
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and words in lines[0], err


def test_fit_writes_a_profile_that_runs_and_knows_where_it_came_from(sdt_main, tmp_path):
    out = tmp_path / "fitted.toml"
    code, stdout, err = sdt_main(
        "twin", "fit", str(DATA / "SSX66115.IDE"), "--sensor", "adxl345", "--out", str(out)
    )
    assert code == 0, err
    assert "scale_error_pct" in stdout and "kept at adxl345's value" in stdout
    code, stdout, err = sdt_main(
        "--sensor-file", str(out), "twin", "check", str(DATA / "SSX66115.IDE"),
        "--sensor", "adxl345-fitted",
    )  # fmt: skip
    assert code == 0, err
    assert "IN-SAMPLE" in stdout and "(in-sample)" in stdout
    code, stdout, err = sdt_main(
        "--sensor-file", str(out), "validate-noise", "--sensor", "adxl345-fitted"
    )
    assert code == 0, err


def test_the_adxl357_pair_names_the_reference_as_the_one_off(registry, readers):
    """DAQ12006: the ADXL357 reads gravity as 1 g (its raw mean vector, read here with idelib)
    and 1.6 x the piezo at the tone: the piezo's calibration is off, and its 100 g floor lies
    above the ADXL357's, so no floor there is judged."""
    raw = _raw("DAQ12006_000005.IDE", 80)[1:4]
    static = float(np.linalg.norm(raw.mean(axis=1)))
    assert static == pytest.approx(1.0, abs=0.01)
    result = check_twin(load_pair(DATA / "DAQ12006_000005.IDE", "adxl357", readers=readers),
                        registry.sensor("adxl357"))  # fmt: skip
    k = result.calibration
    assert k.static_g == pytest.approx(static, abs=0.005)  # the aligned overlap's mean
    assert 1.5 < k.tone_gain < 1.75 and k.reference_off
    assert not any(f.judgeable for f in result.floors)
    assert all(f.reference_ug > f.device_ug for f in result.floors)


def test_a_pair_at_rest_keeps_its_axes_as_mounted(registry, readers):
    """XS5E25D40 is at rest (1 g on z, no shaker): no twin axis correlates with the device
    by 0.5, so no rotation is fitted to noise (which gave 28-40 degree 'angles')."""
    pair = load_pair(DATA / "XS5E25D40.IDE", "adxl357", readers=readers)
    result = check_twin(pair, registry.sensor("adxl357"))
    a = result.alignment
    assert not a.rotation_estimated
    assert np.array_equal(np.array(a.rotation), np.eye(3))
    assert a.correlation < 0.5
