"""Filter stages checked against their analytic frequency response."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.signal import sosfreqz

from sdt_framework.chain import LowPass, RunContext, build_stages, design_lowpass, is_skipped
from sdt_framework.specs import SensorSpec

F_REF = 20000.0


def _filters(sensor: SensorSpec) -> list[tuple[int, float, float]]:
    out = [
        (sensor.mech_order, sensor.mech_cutoff_hz, F_REF),
        (sensor.analog_order, sensor.analog_cutoff_hz, F_REF),
    ]
    if sensor.digital_order is not None and sensor.digital_cutoff_hz is not None:
        out.append((sensor.digital_order, sensor.digital_cutoff_hz, sensor.sampling_rate_hz))
    return out


def test_every_filter_is_3db_down_at_its_cutoff(mems: SensorSpec) -> None:
    for order, cutoff, fs in _filters(mems):
        sos = design_lowpass(order, cutoff, fs)
        assert sos is not None
        assert sos.shape == ((order + 1) // 2, 6)
        _, h = sosfreqz(sos, worN=[0.0, cutoff], fs=fs)
        assert abs(h[0]) == pytest.approx(1.0, abs=1e-9)
        assert 20 * np.log10(abs(h[1])) == pytest.approx(-3.0103, abs=1e-3)


def test_lowpass_stage_passes_a_tone_at_cutoff_with_gain_one_over_root_two() -> None:
    fs, fc = 20000.0, 1500.0
    stage = LowPass("analog", fs, design_lowpass(1, fc, fs))
    t = np.arange(40000) / fs
    y = stage.apply(np.sin(2 * np.pi * fc * t)[None, :], RunContext(threads=1))[0]
    tail = y[-20000:]  # steady state: 1 s, 1500 whole cycles
    amplitude = 2 * np.abs(np.fft.rfft(tail))[1500] / tail.size
    assert amplitude == pytest.approx(1 / np.sqrt(2), rel=1e-3)


def test_filter_at_or_above_nyquist_is_skipped() -> None:
    assert is_skipped(10000, 20000) and is_skipped(30000, 20000)
    assert not is_skipped(9999, 20000)
    assert design_lowpass(1, 10000, 20000) is None
    assert design_lowpass(2, 30000, 20000) is None


def test_reference_chain_at_its_own_rate_has_no_stage(reference: SensorSpec) -> None:
    assert build_stages(reference, 20000) == ()


def test_reference_chain_at_a_higher_rate_keeps_what_is_below_nyquist(
    reference: SensorSpec,
) -> None:
    names = [s.name for s in build_stages(reference, 40000)]
    assert names == ["analog", "sample"]  # 30 kHz >= 20 kHz Nyquist: skipped


def test_mems_stage_order_follows_the_spec(mems: SensorSpec) -> None:
    stages = build_stages(mems, F_REF)
    assert [s.name for s in stages] == [
        "mechanical",
        "analog",
        "sample",
        "noise",
        "digital",
        "quantise",
    ]
    assert [s.fs_out for s in stages][-1] == mems.sampling_rate_hz


def test_designs_are_cached_and_read_only() -> None:
    first = design_lowpass(8, 1000, 4000)
    assert first is design_lowpass(8, 1000.0, 4000.0)
    assert first is not None and not first.flags.writeable
