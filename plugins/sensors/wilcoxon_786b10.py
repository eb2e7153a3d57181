"""Reference chain: Wilcoxon 786B-10 piezo accelerometer with an NI DAQ at 20 kHz.

This is the chain that recorded NLN-EMP, so its profile leaves a 20 kHz
recording unchanged: its 30 kHz and 10 kHz filters sit at or above the 10 kHz
Nyquist frequency (skipped), the recording already carries this chain's noise
(``inject_noise=False``) and was already digitised by its ADC
(``requantise=False``). Paper Table 1 and the Table 4 footnote (SD 0.0).
"""

from __future__ import annotations

from sdt_framework import SensorSpec, hookimpl
from sdt_framework.specs.supply import Supply, SupplyFigure

_NOT_READ = (
    "the Wilcoxon 786B-10 datasheet was not found in the stored copies searched; an IEPE "
    "sensor's constant-current excitation depends on the conditioner, so no figure is assumed"
)
#: No supply figures: the reference chain is a wired IEPE sensor, not a battery node part.
SUPPLY = Supply(
    measure_ua=SupplyFigure(absent=_NOT_READ),
    standby_ua=SupplyFigure(absent=_NOT_READ),
    turn_on_ms=SupplyFigure(absent=_NOT_READ),
)

WILCOXON_786B10 = SensorSpec(
    name="wilcoxon-786b10",
    description="Reference: Wilcoxon 786B-10 IEPE piezo + NI DAQ 24-bit at 20 kHz",
    source="Wilcoxon 786B-10 datasheet; NLN-EMP (Bruinsma et al., 2024); paper Table 1",
    sampling_rate_hz=20000,
    full_scale_g=80,
    adc_bits=24,
    noise_density_ug_rthz=5,
    inject_noise=False,
    requantise=False,
    mech_cutoff_hz=30000,
    mech_order=2,
    analog_cutoff_hz=10000,
    analog_order=1,
    supply=SUPPLY,
)


@hookimpl
def register_sensors(register):
    """Register the reference chain profile."""
    register(WILCOXON_786B10)
