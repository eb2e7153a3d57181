"""The order-domain feature sets (``orders``, ``bearing-orders``) against hand calculations.

Each expected value is worked out here from the signal's construction: a pure
line of amplitude a has RMS a / sqrt 2, so a band that holds it (and nothing
else) reads a / sqrt 2; its velocity is a g / (2 pi f) and its displacement
a g / (2 pi f)^2; an amplitude-modulated carrier A (1 + m cos 2 pi f_m t) has
the envelope A (1 + m cos 2 pi f_m t), whose line at f_m has RMS A m / sqrt 2.
Bearing orders are computed here from the 6309's geometry as pump_rig.toml
gives it (8 balls of 17.46 mm on a 72.5 mm pitch circle, contact angle 0).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.signal import windows as tapers
from sdt_plugins.datasets.pump_rig import rig_machines
from sdt_plugins.features.orders import BEARING_ORDERS, ORDERS, hann_lines

from sdt_framework import SDTError
from sdt_framework.features import extract
from sdt_framework.specs import FeatureContext

FS = 3200.0
G = 9.80665
SECONDS = 4.0
T = np.arange(int(SECONDS * FS)) / FS


def _features(x: np.ndarray, rpm: float, spec=ORDERS, fs: float = FS, **context) -> dict:
    table = extract(x, fs, spec, context=FeatureContext(rpm / 60.0, **context))
    return dict(zip(table.names, np.median(table.values, axis=0), strict=True))


@pytest.mark.parametrize("k", [1, 2, 3])
def test_a_line_at_k_times_the_speed_is_its_rms_in_the_kx_band_only(k: int) -> None:
    rpm, a = 1480.0, 0.25
    x = a * np.sin(2 * np.pi * k * rpm / 60 * T + 0.3)
    got = _features(x, rpm)
    assert got[f"A_{k}X"] == pytest.approx(a / np.sqrt(2), rel=1e-3)
    for other in {1, 2, 3} - {k}:
        assert got[f"A_{other}X"] < 1e-3 * a  # the Hann side lobes die out within an order


def test_moving_the_speed_moves_the_line_but_not_the_order_feature() -> None:
    a = 0.4
    at_speed = {}
    for rpm in (1480.0, 1110.0, 740.0):
        x = a * np.sin(2 * np.pi * 2 * rpm / 60 * T)  # the 2x line, at 49.3, 37.0, 24.7 Hz
        at_speed[rpm] = _features(x, rpm)
    for rpm, got in at_speed.items():
        assert got["A_2X"] == pytest.approx(a / np.sqrt(2), rel=2e-3), rpm
        assert got["A_1X"] < 1e-3 * a and got["A_3X"] < 1e-3 * a
    # read at the wrong speed, the line leaves the 2x band: the speed is what places it
    x = a * np.sin(2 * np.pi * 2 * 1480 / 60 * T)
    assert _features(x, 1110.0)["A_2X"] < 1e-2 * a  # 5 FFT lines off the band: a side lobe


def test_velocity_and_displacement_weight_each_line_by_its_frequency() -> None:
    rpm = 1480.0
    lines = {1 * rpm / 60: 0.1, 5 * rpm / 60: 0.3, 30 * rpm / 60: 0.2}  # 24.7, 123, 740 Hz
    x = sum(a * np.sin(2 * np.pi * f * T) for f, a in lines.items())
    got = _features(x, rpm)
    v = np.sqrt(sum((a * G / (2 * np.pi * f)) ** 2 / 2 for f, a in lines.items())) * 1e3
    d = np.sqrt(sum((a * G / (2 * np.pi * f) ** 2) ** 2 / 2 for f, a in lines.items())) * 1e6
    assert got["V_ORD"] == pytest.approx(v, rel=3e-3)
    # D weights each FFT line by 1 / f^4: the 24.7 Hz line's Hann main lobe (power 1/4, 1,
    # 1/4 on lines 1.5625 Hz apart) reads (1 + (1.30 + 0.79) / 4) / 1.5 = 1.015 of its power,
    # 0.75 % high in RMS; a spectral weighting's known bias, not a scale error
    assert got["D_ORD"] == pytest.approx(d, rel=1e-2)


def test_the_envelope_reads_a_modulation_at_the_bearings_defect_order() -> None:
    rpm, carrier, depth = 1480.0, 1200.0, 0.5
    bpfo = 8 / 2 * (1 - 17.46 / 72.5)  # 6309, contact angle 0: 3.037 orders
    f_m = bpfo * rpm / 60  # 74.9 Hz
    x = (1 + depth * np.cos(2 * np.pi * f_m * T)) * np.sin(2 * np.pi * carrier * T)
    motor = rig_machines()["Motor-2"]
    got = _features(x, rpm, BEARING_ORDERS, machine=motor, channel="ch2")
    assert got["ENV_BPFO"] == pytest.approx(depth / np.sqrt(2), rel=5e-3)
    assert got["ENV_BPFI"] < 0.01 and got["ENV_BSF"] < 0.01
    # the shaft set's envelope at 1x: the same signal modulated at 1x instead
    x1 = (1 + depth * np.cos(2 * np.pi * rpm / 60 * T)) * np.sin(2 * np.pi * carrier * T)
    assert _features(x1, rpm)["ENV_1X"] == pytest.approx(depth / np.sqrt(2), rel=5e-3)


@pytest.mark.parametrize("n", [8, 9, 2048, 2047])
def test_the_hann_spectrum_from_the_plain_one_is_the_windowed_fft(n: int) -> None:
    x = np.random.default_rng(n).normal(size=(3, n))
    expected = np.fft.rfft(x * tapers.hann(n, sym=False), axis=1)
    np.testing.assert_allclose(hann_lines(np.fft.rfft(x, axis=1), n), expected, atol=1e-12)


def test_an_order_band_above_nyquist_is_refused_naming_the_band_speed_and_rate() -> None:
    x = np.random.default_rng(0).normal(size=2 * 1600)
    with pytest.raises(SDTError) as error:
        extract(x, 1600.0, ORDERS, context=FeatureContext(1480 / 60, "given: test"))
    message = str(error.value)
    assert "\n" not in message
    # 40.2 orders x 24.67 Hz = 986.7 Hz above the 800 Hz Nyquist frequency of 1600 Hz
    for part in ("'0.4-40 orders'", "1480 rpm", "986.7 Hz", "Nyquist frequency 800 Hz",
                 "fs=1600 Hz"):  # fmt: skip
        assert part in message, message
    # at 1110 rpm the same band ends at 744 Hz: the rate holds it
    extract(x, 1600.0, ORDERS, context=FeatureContext(1110 / 60))


def test_a_set_in_orders_without_a_speed_is_refused() -> None:
    x = np.random.default_rng(0).normal(size=int(2 * FS))
    with pytest.raises(SDTError, match=r"feature set 'orders' works in orders .* needs the"):
        extract(x, FS, ORDERS)


def test_bearing_orders_on_a_machine_listing_no_bearings_is_refused() -> None:
    x = np.random.default_rng(0).normal(size=int(2 * FS))
    context = FeatureContext(2075 / 60, machine=rig_machines()["Motor-4"], recording="r1")
    with pytest.raises(SDTError, match=r"^machine 'Motor-4' lists no bearings, so feature set "):
        extract(x, FS, BEARING_ORDERS, context=context)


def test_the_api_takes_the_set_by_name_with_its_context() -> None:
    from sdt_framework.api import extract as api_extract

    x = 0.3 * np.sin(2 * np.pi * 2 * 1480 / 60 * T)
    table = api_extract(x, FS, "orders", context=FeatureContext(1480 / 60, "given: test"))
    assert table.feature_set == "orders" and table.speed == "1480 rpm (24.67 Hz; given: test)"
    assert np.median(table.values[:, 1]) == pytest.approx(0.3 / np.sqrt(2), rel=1e-3)
