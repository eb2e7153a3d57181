"""Every band a figure measures lies inside what the sensor's chain passes, and says so.

Issue 40: Fig. 4 labelled a LIS3DH in high-resolution mode (1344 Hz, ODR/9 =
149 Hz digital low-pass) "NSD 100.9 µg/√Hz" against its configured 220,
because the 10-1500 Hz band ran far past the chain's bandwidth.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import signal

from sdt_framework.report.figures_signal import plot_noise
from sdt_framework.report.signals import noise_checks
from sdt_framework.report.style import save_figure, sensor_colors
from sdt_framework.specs import SensorSpec

from .conftest import assert_real_png

#: the catalogue's lis3dh[mode=hr] as the datasheet gives it (DocID17530 Rev 2, Tables 4, 10, 31)
LIS3DH_HR = SensorSpec(
    name="lis3dh-hr",
    sampling_rate_hz=1344,
    full_scale_g=2,
    adc_bits=12,
    noise_density_ug_rthz=220,
    mech_cutoff_hz=None,
    analog_cutoff_hz=672,
    digital_cutoff_hz=1344 / 9,
    digital_order=8,
)


def _butterworth_mean_power(order: int, cutoff: float, band: tuple[float, float]) -> float:
    """Mean of |H|^2 = 1 / (1 + (f/fc)^2n) over ``band`` (the analog prototype, by hand)."""
    f = np.linspace(*band, 20001)
    return float(np.mean(1.0 / (1.0 + (f / cutoff) ** (2 * order))))


def test_fig4_nsd_of_a_narrow_chain_is_read_under_its_bandwidth(tmp_path) -> None:
    (noise,) = noise_checks([LIS3DH_HR], seed=0)
    top = 1344 / 9
    assert noise.check.band_hz == pytest.approx((10.0, top))
    # independent: white noise of 220 µg/√Hz through the 8th-order low-pass, mean power in band
    expected = 220 * np.sqrt(_butterworth_mean_power(8, top, (10.0, top)))
    measured = float(noise.check.sdt.nsd_ug_rthz.mean())
    assert measured == pytest.approx(expected, rel=0.06)  # 8 windows: ~3 % scatter
    # and recomputed from the zero-motion output with scipy's Welch over the same band
    windows = noise.check.sdt_signal[: 8 * 2048].reshape(8, 2048)
    freqs, psd = signal.welch(windows, fs=1344, nperseg=2048, axis=-1)
    keep = (freqs >= 10) & (freqs <= top)
    assert measured == pytest.approx(np.mean(np.sqrt(psd[:, keep].mean(axis=1)) * 1e6))
    # the old 10-1500 Hz reading was about half the configured density
    old = np.sqrt(psd[:, freqs >= 10].mean(axis=1)).mean() * 1e6
    assert old < 0.6 * 220
    caption = noise.caption()
    assert f"NSD {measured:.1f} µg/√Hz over 10-149 Hz" in caption
    assert "configured 220; 10-1500 Hz clipped to 10-149 Hz by its 149 Hz digital low-pass" in (
        caption
    )
    fig = plot_noise([noise], sensor_colors(["lis3dh-hr"], None))
    dashed = [c for c in fig.axes[1].collections if c.get_linestyle()[0][1] is not None]
    (segment,) = dashed[0].get_segments()
    assert segment[:, 0] == pytest.approx([10.0, top])  # the NSD is drawn over its band only
    assert_real_png(save_figure(fig, tmp_path, "noise.png"))


def test_fig4_keeps_the_whole_band_where_the_chain_passes_it(registry) -> None:
    (noise,) = noise_checks([registry.sensor("adxl345")], seed=0)
    assert noise.check.band_hz == (10.0, 1500.0) and noise.check.band_note == ""
    assert "over 10-1500 Hz (configured 290)" in noise.caption()


def test_validate_noise_reads_the_nsd_where_the_chain_passes(tmp_path) -> None:
    """``sdt validate-noise`` and its JSON read the same band as Fig. 4 (one mechanism,
    :func:`sdt_framework.chain.passband`), and say so in one warning line."""
    import json

    from typer.testing import CliRunner

    from sdt_framework.cli.main import app

    toml = tmp_path / "lis3dh-hr.toml"
    toml.write_text(
        'name = "lis3dh-hr"\nsampling_rate_hz = 1344\nfull_scale_g = 2\nadc_bits = 12\n'
        "noise_density_ug_rthz = 220\nmech_cutoff_hz = 5000\nanalog_cutoff_hz = 672\n"
        f"digital_cutoff_hz = {1344 / 9!r}\ndigital_order = 8\n",
        encoding="utf-8",
    )
    base = ["--sensor-file", str(toml), "validate-noise", "--sensor", "lis3dh-hr"]
    result = CliRunner().invoke(app, [*base, "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    top = 1344 / 9
    assert data["band_hz"] == pytest.approx([10.0, top])
    expected = 220 * np.sqrt(_butterworth_mean_power(8, top, (10.0, top)))
    assert data["sdt"]["nsd_ug_rthz"] == pytest.approx(expected, rel=0.06)
    text = CliRunner().invoke(app, base)
    assert (
        "warning: NSD read over 10-149 Hz: 10-1500 Hz clipped to 10-149 Hz by its 149 Hz "
        "digital low-pass"
    ) in " ".join(text.output.split())
