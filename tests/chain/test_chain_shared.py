"""Shared recording-rate prefix: bit-identical to independent degrade, computed once."""

from __future__ import annotations

import numpy as np

from sdt_framework.api import degrade
from sdt_framework.chain.chain import compile_chain
from sdt_framework.chain.shared import SharedPrefix, prefix_key, split_chain
from sdt_framework.specs import SensorSpec

FS = 20000.0


def sensor(name: str, **changes) -> SensorSpec:
    fields = dict(
        name=name,
        sampling_rate_hz=3200,
        full_scale_g=16,
        adc_bits=13,
        noise_density_ug_rthz=290,
        mech_cutoff_hz=7000,
        analog_cutoff_hz=1600,
        digital_cutoff_hz=1599,
        digital_order=1,
    )
    return SensorSpec(**{**fields, **changes})


def test_shared_prefix_equals_independent_degrade_bit_for_bit():
    x = np.random.default_rng(3).standard_normal((3, 40000))
    sensors = [
        sensor("a"),
        sensor("b", sampling_rate_hz=1600, digital_cutoff_hz=799),  # same prefix as a
        sensor("c", noise_density_ug_rthz=25, adc_bits=16),  # same prefix
        sensor("d", analog_cutoff_hz=1000),  # another prefix
        sensor(
            "e",
            sampling_rate_hz=20000,
            digital_cutoff_hz=None,
            digital_order=None,
            inject_noise=False,
            requantise=False,
            mech_cutoff_hz=30000,
            analog_cutoff_hz=10000,
        ),  # identity-like reference at the recording rate
    ]
    shared = SharedPrefix(x, FS)
    for s in sensors:
        for seed in (0, 7):
            got, fs_got = shared.degrade(s, seed)
            want, fs_want = degrade(x, FS, s, seed, threads=1)
            assert fs_got == fs_want
            assert np.array_equal(got, want)
    # a, b, c share one prefix; d and e have their own: 3 groups, and the calls
    # above visit them in that order, so each prefix is computed once
    keys = [prefix_key(s, FS) for s in sensors]
    assert keys[0] == keys[1] == keys[2] != keys[3]
    assert shared.prefix_runs == 3


def test_the_prefix_holds_only_recording_rate_analog_stages():
    prefix, rest = split_chain(compile_chain(sensor("a"), FS))
    assert [s.name for s in prefix.stages] == ["mechanical+analog"]
    assert all(s.fs_in == FS for s in prefix.stages)
    assert [type(s).__name__ for s in rest.stages] == [
        "Sample",
        "WhiteNoise",
        "LowPass",
        "Quantise",
    ]
