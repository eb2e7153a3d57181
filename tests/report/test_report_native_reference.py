"""The report's signal figure takes a chain without range or converter (native-reference)."""

from __future__ import annotations

import numpy as np

from sdt_framework import build_registry
from sdt_framework.report.signals import degrade_all


class _Recording:
    """A 25.6 kHz recording, as a DAQ writes it (no 20 kHz: the reference is native)."""

    recording_id = "daq/ch1"
    sampling_rate_hz = 25600.0

    def load(self) -> np.ndarray:
        t = np.arange(25600) / 25600.0
        return np.sin(2 * np.pi * 80.0 * t)[None, :]


def test_native_reference_neither_clips_nor_quantises_in_the_signal_figure():
    registry = build_registry()
    x, traces = degrade_all(_Recording(), [registry.sensor("native-reference")])
    (trace,) = traces
    assert trace.full_scale_g == np.inf and trace.lsb_g == 0.0 and not trace.clipped
    # the native chain passes the recording through at its own rate
    assert trace.fs == 25600.0 and np.allclose(trace.signal, x, atol=1e-6)


def test_native_reference_bandwidth_is_the_recordings():
    """Its rate is the recording's (not a number on the spec): the envelope band stays below fs."""
    from sdt_framework.severity.spectra import chain_bandwidth, envelope_band

    bandwidth = chain_bandwidth(build_registry().sensor("native-reference"))
    assert bandwidth == np.inf
    low, high = envelope_band(12000.0, bandwidth)
    assert high == 0.45 * 12000.0 and low == high / 4
