"""What each sensor's envelope band holds: the recording's own band, or content folded into it.

Envelope analysis band-passes a structural resonance that the bearing's
impacts ring and demodulates it. The reference's chain passes the resonance;
a MEMS chain whose output Nyquist lies below it either folds it into its own
band (the paper's sample-then-filter model, and a SAR part without an
anti-alias filter) or attenuates it in its decimation filter (a sigma-delta
part). In the first case the MEMS envelope still shows the defect lines, but
from aliased content: lines a real part of that family would not show. The
figure must say which, and for every resonance, not only the strongest: on the
pump bearing the 4.3 kHz mode folds through the ADXL345 to 0.9-1.3 kHz,
outside its 200-800 Hz envelope band, while the 6.1 kHz mode folds to 300 Hz,
inside it.

:func:`envelope_content` therefore asks, line by line over the recording's
spectrum, where each line lands in the chain and with what gain
(:func:`sdt_framework.chain.chain_gain`), and sums the power that arrives in
the sensor's envelope band: the share that arrives from above the output
Nyquist is aliased. The largest aliased source is named with
:func:`sdt_framework.chain.band_fate`; where nothing aliased arrives, the
recording's strongest resonance (:func:`excited_band`) is named with what the
chain does to it (passed, or attenuated by its decimation filter).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal

from ..chain import BandFate, band_fate, chain_gain
from ..specs import SensorSpec

__all__ = ["EnvelopeContent", "envelope_content", "excited_band"]

#: resolution of the spectrum the content is read from, Hz (a bearing housing's mode at
#: a few kHz with 2-5 % damping is 100-500 Hz wide at half power)
RESOLUTION_HZ = 20.0
#: lines of the running mean that smooths the spectrum before a half-power band is read
SMOOTH_LINES = 3
#: an envelope band holding at least this share of aliased power "shows aliased content"
ALIASED_SHARE = 0.5


def _spectrum(x: np.ndarray, fs: float) -> tuple[np.ndarray, np.ndarray]:
    """Welch PSD (Hann, 50 % overlap) at about :data:`RESOLUTION_HZ`, DC line left out."""
    nperseg = int(min(len(x), 2 ** round(np.log2(fs / RESOLUTION_HZ))))
    freq, power = signal.welch(np.asarray(x, dtype=float), fs=fs, nperseg=nperseg)
    return freq[1:], power[1:]


def _half_power(freq: np.ndarray, power: np.ndarray, peak: int) -> tuple[float, float]:
    """The band around line ``peak`` out to the last lines at half its power or more."""
    below = np.flatnonzero(power < power[peak] / 2)
    left, right = below[below < peak], below[below > peak]
    lo = freq[left[-1] + 1] if left.size else freq[0]
    hi = freq[right[0] - 1] if right.size else freq[-1]
    step = freq[1] - freq[0] if freq.size > 1 else 1.0
    return float(lo), float(max(hi, lo + step))


def excited_band(x: np.ndarray, fs: float, search_hz: tuple[float, float]) -> tuple[float, float]:
    """Half-power band (Hz) around the strongest peak of ``x``'s spectrum within ``search_hz``.

    The spectrum is smoothed by a running mean over :data:`SMOOTH_LINES` lines
    first (one low estimate must not cut the band: a 2 s recording's PSD
    scatters by about 10 % per line); its half-power width is 2 zeta f for a
    lightly damped mode.
    """
    freq, power = _spectrum(x, fs)
    power = np.convolve(power, np.ones(SMOOTH_LINES) / SMOOTH_LINES, mode="same")
    inside = np.flatnonzero((freq >= search_hz[0]) & (freq <= search_hz[1]))
    return _half_power(freq, power, int(inside[np.argmax(power[inside])]))


@dataclass(frozen=True)
class EnvelopeContent:
    """Where the recording's content in ``sensor``'s envelope band comes from.

    ``aliased_share``: the share of the power arriving in the envelope band that
    comes from above the output Nyquist. ``source``: the fate of the largest
    aliased source band, or, when nothing aliased arrives, of the recording's
    strongest resonance; ``source_share``: that source's share of the arriving
    power.
    """

    sensor: str
    envelope_hz: tuple[float, float]
    aliased_share: float
    source: BandFate
    source_share: float

    @property
    def aliased_into_envelope(self) -> bool:
        """True when most of what this envelope demodulates was folded into its band."""
        return self.aliased_share >= ALIASED_SHARE

    def short(self) -> str:
        """A few words for the panel."""
        f = self.source
        band = f"{f.band_hz[0] / 1e3:.2f}-{f.band_hz[1] / 1e3:.2f} kHz"
        head = f"envelope band {self.aliased_share:.0%} aliased"
        if f.folded_hz is not None:
            folded = f"{f.folded_hz[0]:.0f}-{f.folded_hz[1]:.0f} Hz"
            return f"{head}: {band} folded to {folded} at {f.gain_db:+.0f} dB"
        if f.kind == "passed":
            return f"{head}; resonance {band} passed ({f.gain_db:+.0f} dB)"
        return f"{head}; resonance {band} attenuated by {-f.gain_db:.0f} dB"

    def describe(self) -> str:
        """One sentence for the caption."""
        f = self.source
        lo, hi = f.band_hz
        env = f"{self.envelope_hz[0]:.0f}-{self.envelope_hz[1]:.0f} Hz envelope band"
        head = f"{self.sensor}: {self.aliased_share:.0%} of what reaches its {env} is aliased"
        if f.folded_hz is not None:
            text = (
                f"{head} ({self.source_share:.0%} from {lo:.0f}-{hi:.0f} Hz, above its "
                f"{f.nyquist_hz:g} Hz output Nyquist, folded to {f.folded_hz[0]:.0f}-"
                f"{f.folded_hz[1]:.0f} Hz at {f.gain_db:+.1f} dB, {f.sampling})"
            )
            if self.aliased_into_envelope:
                return f"{text}: this envelope shows aliased content"
            return text
        if f.kind == "passed":
            return f"{head}; the {lo:.0f}-{hi:.0f} Hz resonance is passed ({f.gain_db:+.1f} dB)"
        return (
            f"{head}; the {lo:.0f}-{hi:.0f} Hz resonance is attenuated by {-f.gain_db:.0f} dB "
            f"({f.sampling}, output Nyquist {f.nyquist_hz:g} Hz)"
        )


def envelope_content(
    sensor: SensorSpec,
    x: np.ndarray,
    fs: float,
    envelope_hz: tuple[float, float],
    resonance_hz: tuple[float, float],
) -> EnvelopeContent:
    """What of recording ``x`` (at ``fs`` Hz) reaches ``sensor``'s envelope band, and from where.

    Every line of the recording's spectrum is carried to the frequency it lands
    at in the chain, with the chain's gain (:func:`~sdt_framework.chain.chain_gain`);
    the power landing in ``envelope_hz`` is summed. ``resonance_hz`` (see
    :func:`excited_band`) is named when nothing aliased arrives.
    """
    freq, power = _spectrum(x, fs)
    gain, out = chain_gain(sensor, fs, freq)
    nyquist = float(sensor.at_rate(fs).sampling_rate_hz) / 2
    arriving = power * gain**2 * ((out >= envelope_hz[0]) & (out <= envelope_hz[1]))
    aliased = np.where(freq > nyquist, arriving, 0.0)
    total = float(arriving.sum())
    share = float(aliased.sum() / total) if total > 0 else 0.0
    if share > 0 and aliased.max() > 0:
        band = _half_power(freq, aliased, int(np.argmax(aliased)))
        inside = (freq >= band[0]) & (freq <= band[1])
        fate, part = band_fate(sensor, fs, band), float(aliased[inside].sum() / total)
        if fate.kind == "aliased":
            return EnvelopeContent(sensor.name, envelope_hz, share, fate, part)
    return EnvelopeContent(
        sensor.name, envelope_hz, share, band_fate(sensor, fs, resonance_hz), 0.0
    )
