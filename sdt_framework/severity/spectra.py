"""The spectra a vibration engineer reads: envelope, velocity and ASD, with their scaling.

Each function returns a :class:`Spectrum` that carries what a caption must
state: scaling, window, resolution bandwidth (RBW = ENBW x fs / N, with the
Hann window's ENBW of 1.5 bins) and unit.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import signal

__all__ = [
    "G",
    "Spectrum",
    "asd",
    "chain_bandwidth",
    "envelope_band",
    "envelope_spectrum",
    "running_speed",
    "velocity_spectrum",
]

G = 9.80665  # m/s^2 per g
HANN_ENBW = 1.5  # equivalent noise bandwidth of the Hann window, in bins


@dataclass(frozen=True)
class Spectrum:
    """One spectrum and what it is."""

    freq: np.ndarray
    values: np.ndarray
    unit: str
    scaling: str
    window: str
    rbw_hz: float

    @property
    def bin_hz(self) -> float:
        """Spacing of the frequency lines."""
        return float(self.freq[1] - self.freq[0])

    def caption(self) -> str:
        """Scaling, window, resolution bandwidth and unit, as a caption states them."""
        return (
            f"{self.scaling}, {self.window} window, RBW {self.rbw_hz:.3g} Hz "
            f"(line spacing {self.bin_hz:.3g} Hz), unit {self.unit}"
        )


def chain_bandwidth(spec: object) -> float:
    """A sensor chain's usable bandwidth: the lowest of its analog/digital cut-offs and Nyquist."""
    cutoffs = [getattr(spec, name, None) for name in ("analog_cutoff_hz", "digital_cutoff_hz")]
    rate = spec.sampling_rate_hz
    # a chain at the recording's own rate (native-reference): the recording's Nyquist limits
    # it, and envelope_band caps the band at 0.45 x fs
    nyquist = rate / 2 if isinstance(rate, (int, float)) else float("inf")
    return float(min([c for c in cutoffs if c] + [nyquist]))


def envelope_band(fs: float, bandwidth_hz: float, top_hz: float = 8000.0) -> tuple[float, float]:
    """Band-pass for the envelope: two octaves ending at half the chain's bandwidth (<= 8 kHz).

    Impacts ring the housing's kHz resonances; a sensor sees them only up to
    its bandwidth, and the top of a first-order chain's band (the ADXL345's)
    carries what its filter lets alias, so the band is (hi / 4, hi) with
    hi = min(0.5 x bandwidth, 0.45 x fs, ``top_hz``). On the synthetic Motor-2
    outer-race fault this gives 1.25-5 kHz for the reference, 200-800 Hz for
    the ADXL345 and 125-500 Hz for the ADXL357; with 0.9 x bandwidth the
    ADXL345's strongest envelope line was at 190 Hz, not at BPFO.
    """
    high = min(0.5 * bandwidth_hz, 0.45 * fs, top_hz)
    return high / 4, high


def envelope_spectrum(x: np.ndarray, fs: float, band: tuple[float, float]) -> Spectrum:
    """Amplitude spectrum of the Hilbert envelope of ``x`` band-passed to ``band``.

    4th-order Butterworth band-pass (zero phase), envelope |hilbert|, mean
    removed, one Hann-windowed FFT over the whole signal; one-sided peak
    amplitude in g (a sine of amplitude a reads a).
    """
    sos = signal.butter(4, band, btype="bandpass", fs=fs, output="sos")
    envelope = np.abs(signal.hilbert(signal.sosfiltfilt(sos, np.asarray(x, dtype=float))))
    envelope -= envelope.mean()
    window = signal.windows.hann(envelope.size, sym=False)
    amp = 2 * np.abs(np.fft.rfft(envelope * window)) / window.sum()
    freq = np.fft.rfftfreq(envelope.size, 1 / fs)
    return Spectrum(
        freq,
        amp,
        "g",
        f"envelope of {band[0]:.0f}-{band[1]:.0f} Hz band, one-sided peak amplitude",
        "Hann",
        HANN_ENBW * fs / envelope.size,
    )


def velocity_spectrum(
    x: np.ndarray, fs: float, band: tuple[float, float] = (10.0, 1000.0), seconds: float = 2.0
) -> Spectrum:
    """Velocity r.m.s. per line in mm/s over ``band``, from acceleration ``x`` in g.

    Welch power spectrum (scaling "spectrum": each line's mean square),
    Hann window of ``seconds``, 50 % overlap; each line divided by 2 pi f.
    The root of the sum of the lines in 10-1000 Hz is the overall V_RMS.
    """
    nperseg = min(int(seconds * fs), len(x))
    freq, power = signal.welch(x, fs=fs, window="hann", nperseg=nperseg, scaling="spectrum")
    keep = (freq >= band[0]) & (freq <= band[1])
    velocity = np.sqrt(power[keep]) * G * 1e3 / (2 * np.pi * freq[keep])
    return Spectrum(
        freq[keep],
        velocity,
        "mm/s r.m.s.",
        "velocity r.m.s. per line (Welch power spectrum / 2 pi f), 50 % overlap",
        "Hann",
        HANN_ENBW * fs / nperseg,
    )


def asd(x: np.ndarray, fs: float, seconds: float = 0.5) -> Spectrum:
    """Acceleration spectral density, one-sided, g/sqrt(Hz) (Welch, Hann, 50 % overlap)."""
    nperseg = min(int(seconds * fs), len(x))
    freq, density = signal.welch(x, fs=fs, window="hann", nperseg=nperseg, scaling="density")
    return Spectrum(
        freq,
        np.sqrt(density),
        "g/sqrt(Hz)",
        "one-sided amplitude spectral density (Welch), 50 % overlap",
        "Hann",
        HANN_ENBW * fs / nperseg,
    )


def running_speed(x: np.ndarray, fs: float, nominal_hz: float, tolerance: float = 0.03) -> float:
    """The shaft speed read off the spectrum: the largest line within +-3 % of nominal.

    Hann-windowed FFT zero-padded 8 times, parabolic interpolation on the log
    magnitude; the field's way to place defect lines at the speed the machine
    ran, not at its nameplate speed.
    """
    n = len(x)
    window = signal.windows.hann(n, sym=False)
    size = 8 * n
    mag = np.abs(np.fft.rfft((np.asarray(x, float) - np.mean(x)) * window, size))
    freq = np.fft.rfftfreq(size, 1 / fs)
    near = np.flatnonzero(np.abs(freq - nominal_hz) <= tolerance * nominal_hz)
    k = near[np.argmax(mag[near])]
    a, b, c = np.log(mag[k - 1 : k + 2] + 1e-300)
    shift = 0.5 * (a - c) / (a - 2 * b + c) if a - 2 * b + c != 0 else 0.0
    return float((k + shift) * fs / size)
