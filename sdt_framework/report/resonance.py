"""Where the resonance an envelope demodulates lies, and what each sensor's chain makes of it.

Envelope analysis band-passes a structural resonance that the bearing's
impacts ring and demodulates it. The reference's chain passes that resonance;
a MEMS chain whose output Nyquist lies below it either folds it into its own
band (the paper's sample-then-filter model, and a SAR part without an
anti-alias filter) or attenuates it in its decimation filter (a sigma-delta
part). In the first case the MEMS envelope still shows the defect lines, but
from aliased content: a line a real part of that family would not show. The
figure must say which.

:func:`excited_band` finds the resonance in the recording itself: the
half-power band around the strongest peak of its spectrum within the band the
reference's envelope uses. :func:`resonance_fates` asks
:func:`sdt_framework.chain.band_fate` what each chain does to that band.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal

from ..chain import BandFate, band_fate
from ..specs import SensorSpec

__all__ = ["ResonanceFate", "excited_band", "resonance_fates"]

#: resolution of the spectrum the resonance is read from, Hz (a bearing housing's mode
#: at a few kHz with 2-5 % damping is 100-500 Hz wide at half power)
RESOLUTION_HZ = 20.0
#: lines of the running mean that smooths the spectrum before its half-power band is read
SMOOTH_LINES = 3


def excited_band(x: np.ndarray, fs: float, search_hz: tuple[float, float]) -> tuple[float, float]:
    """Half-power band (Hz) around the strongest peak of ``x``'s spectrum within ``search_hz``.

    Welch PSD (Hann, 50 % overlap) at about :data:`RESOLUTION_HZ`, smoothed by a
    running mean over :data:`SMOOTH_LINES` lines (one low estimate must not cut
    the band: a 2 s recording's PSD scatters by about 10 % per line); the band
    runs from the peak out to the last lines on either side still at half its
    power or more (its -3 dB width, 2 zeta f for a lightly damped mode).
    """
    nperseg = int(min(len(x), 2 ** round(np.log2(fs / RESOLUTION_HZ))))
    freq, power = signal.welch(np.asarray(x, dtype=float), fs=fs, nperseg=nperseg)
    power = np.convolve(power, np.ones(SMOOTH_LINES) / SMOOTH_LINES, mode="same")
    inside = np.flatnonzero((freq >= search_hz[0]) & (freq <= search_hz[1]))
    peak = inside[np.argmax(power[inside])]
    below = np.flatnonzero(power < power[peak] / 2)
    left = below[below < peak]
    right = below[below > peak]
    lo = freq[left[-1] + 1] if left.size else freq[0]
    hi = freq[right[0] - 1] if right.size else freq[-1]
    return float(lo), float(max(hi, lo + freq[1]))


@dataclass(frozen=True)
class ResonanceFate:
    """What ``sensor``'s chain does to the resonance, and whether it lands in its envelope band."""

    sensor: str
    fate: BandFate
    envelope_hz: tuple[float, float]

    @property
    def aliased_into_envelope(self) -> bool:
        """True when the resonance folds into the band this sensor's envelope demodulates."""
        if self.fate.kind != "aliased" or self.fate.folded_hz is None:
            return False
        lo, hi = self.fate.folded_hz
        return lo < self.envelope_hz[1] and hi > self.envelope_hz[0]

    def short(self) -> str:
        """A few words for the panel: where the resonance lands in this chain."""
        f = self.fate
        if f.kind == "passed":
            return f"resonance passed ({f.gain_db:+.0f} dB)"
        if f.kind == "attenuated":
            return f"resonance attenuated by {-f.gain_db:.0f} dB"
        assert f.folded_hz is not None
        where = "inside" if self.aliased_into_envelope else "outside"
        return (
            f"resonance aliased to {f.folded_hz[0]:.0f}-{f.folded_hz[1]:.0f} Hz at "
            f"{f.gain_db:+.0f} dB, {where} its envelope band"
        )

    def describe(self) -> str:
        """One sentence for the caption."""
        f = self.fate
        lo, hi = f.band_hz
        env = f"{self.envelope_hz[0]:.0f}-{self.envelope_hz[1]:.0f} Hz"
        head = f"{self.sensor}: the {lo:.0f}-{hi:.0f} Hz resonance"
        if f.kind == "passed":
            return f"{head} is passed ({f.gain_db:+.1f} dB); its {env} envelope demodulates it"
        if f.kind == "attenuated":
            where = "above" if hi > f.nyquist_hz else "below"
            return (
                f"{head} ({where} its {f.nyquist_hz:g} Hz output Nyquist) is attenuated by "
                f"{-f.gain_db:.0f} dB ({f.sampling}): its {env} envelope holds in-band "
                f"content only"
            )
        assert f.folded_hz is not None
        text = (
            f"{head} lies above its {f.nyquist_hz:g} Hz output Nyquist and folds to "
            f"{f.folded_hz[0]:.0f}-{f.folded_hz[1]:.0f} Hz at {f.gain_db:+.1f} dB ({f.sampling})"
        )
        if self.aliased_into_envelope:
            return f"{text}, inside its {env} envelope band: this envelope shows aliased content"
        return f"{text}, outside its {env} envelope band"


def resonance_fates(
    specs: list[SensorSpec],
    fs: float,
    band_hz: tuple[float, float],
    envelope_bands: dict[str, tuple[float, float]],
) -> dict[str, ResonanceFate]:
    """Per sensor, what its chain (on a recording at ``fs`` Hz) does to ``band_hz``."""
    return {
        s.name: ResonanceFate(s.name, band_fate(s, fs, band_hz), envelope_bands[s.name])
        for s in specs
    }
