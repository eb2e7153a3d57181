"""The synthetic pump's triaxial node (``triaxial = true``): off by default, same physics.

With the option the generator adds ch6, the horizontal axis of a node on the motor
drive-end housing whose vertical and axial axes are ch2 and ch3. The paper's five
channels must not change with it, and the node's horizontal and vertical axes must
see the shaft's rotating force a quarter turn apart, as any two radial sensors 90
degrees apart on one housing do.
"""

from __future__ import annotations

import numpy as np
from sdt_plugins.datasets.synthetic_pump import model as m
from sdt_plugins.datasets.synthetic_pump import open_synthetic


def _signals(**options) -> dict[str, np.ndarray]:
    ds = open_synthetic(seed=2, duration=4.0, machines="Motor-4", conditions="healthy", **options)
    return {r.channel: r.load()[0] for r in ds.recordings() if r.run == "healthy 1"}


def test_the_node_is_off_by_default_and_changes_nothing_else():
    plain = _signals()
    node = _signals(triaxial=True)
    assert sorted(plain) == ["ch1", "ch2", "ch3", "ch4", "ch5"]
    assert sorted(node) == [*sorted(plain), "ch6"]
    for channel, values in plain.items():
        np.testing.assert_array_equal(node[channel], values)
    assert m.NODE_AXES == {"ch6": "x", "ch2": "y", "ch3": "z"}


def test_horizontal_and_vertical_axes_see_the_rotating_force_90_degrees_apart():
    node = _signals(triaxial=True)
    fs = 20_000.0
    shaft = m.MACHINES["Motor-4"].rpm / 60
    spectra = {ch: np.fft.rfft(node[ch] * np.hanning(node[ch].size)) for ch in ("ch6", "ch2")}
    f = np.fft.rfftfreq(node["ch6"].size, 1 / fs)
    near = np.flatnonzero(np.abs(f - shaft) < 0.5)
    k = near[np.argmax(np.abs(spectra["ch2"][near]))]
    lag = np.degrees(np.angle(spectra["ch2"][k] / spectra["ch6"][k]))
    # ch2's radial gains are ch6's times j (90 degrees); the axial share (same phase in
    # both, about 6 % of the 1x line) may pull the difference by a few degrees
    assert abs(abs(lag) - 90) < 10, lag
