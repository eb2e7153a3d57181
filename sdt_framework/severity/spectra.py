"""The spectra a vibration engineer reads: envelope, velocity and ASD, with their scaling.

Each function returns a :class:`Spectrum` that carries what a caption must
state: scaling, window, resolution bandwidth (RBW = ENBW x fs / N, the
window's equivalent noise bandwidth in lines: 1.5 for Hann, 3.77 for the
flat-top window) and unit. The velocity spectrum also carries its overall
value, computed with the window's ENBW (a sum of "spectrum"-scaled lines
without it reads a sine 22.5 % high under Hann: sqrt(1.5) = 1.2247).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import signal

from ..chain import passband
from ..errors import SDTError
from ..specs import SensorSpec
from ..units import G_N

__all__ = [
    "LOW_EDGE_LINES",
    "Spectrum",
    "asd",
    "chain_bandwidth",
    "envelope_band",
    "envelope_spectrum",
    "velocity_spectrum",
]

#: a band's low edge must lie at least this many lines above 0 Hz: the band edge is then
#: placed to a quarter of itself, clear of the Hann main lobe (2 lines) of what lies below
LOW_EDGE_LINES = 4


def enbw_lines(window: np.ndarray) -> float:
    """Equivalent noise bandwidth of ``window`` in lines: N sum(w^2) / (sum w)^2."""
    return float(window.size * np.sum(window**2) / np.sum(window) ** 2)


@dataclass(frozen=True)
class Spectrum:
    """One spectrum and what it is.

    ``overall`` is the r.m.s. over the spectrum's band where it has one (the
    velocity spectrum): the root of the sum of the lines' mean squares divided
    by the window's ENBW in lines (``enbw``). ``band_hz`` is the band the lines
    cover, ``note`` says why it differs from the band asked for (empty if not).
    """

    freq: np.ndarray
    values: np.ndarray
    unit: str
    scaling: str
    window: str
    rbw_hz: float
    enbw: float = 1.5
    overall: float | None = None
    band_hz: tuple[float, float] | None = None
    note: str = ""

    @property
    def bin_hz(self) -> float:
        """Spacing of the frequency lines."""
        return float(self.freq[1] - self.freq[0])

    def caption(self) -> str:
        """Scaling, window, resolution bandwidth and unit, as a caption states them."""
        text = (
            f"{self.scaling}, {self.window} window, RBW {self.rbw_hz:.3g} Hz "
            f"(line spacing {self.bin_hz:.3g} Hz), unit {self.unit}"
        )
        return f"{text} ({self.note})" if self.note else text


def chain_bandwidth(spec: SensorSpec) -> float:
    """A sensor chain's usable bandwidth: its lowest mechanical, analog or digital corner, or
    its output Nyquist frequency, by the chain's own rule (:func:`~sdt_framework.chain.passband`).

    No recording's rate bounds it here (an unbounded one is given), so a chain at the
    recording's own rate (native-reference) has no bound (inf): ``envelope_band`` caps
    the band at 0.45 x fs of the recording it reads.
    """
    return passband(spec, math.inf).top_hz


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
    """Amplitude spectrum of the Hilbert envelope of ``x`` band-passed to ``band``, in gE.

    4th-order Butterworth band-pass (zero phase), envelope |hilbert|, mean
    removed, one flat-top-windowed FFT over the whole signal; one-sided peak
    amplitude of each line (an envelope modulated by a cos(2 pi f t) reads a at
    f, wherever f falls between two lines: the flat-top window's scalloping is
    under 0.2 %, where Hann's reached 15 %). The unit gE is the field's name for
    enveloped acceleration; here it means this envelope in g. Each vendor sets
    its own filters and detector (SKF's ENV1-ENV4 bands, a rectifier and a
    low-pass), so these gE compare sensors with each other, not with another
    instrument's gE (docs/severity.md).
    """
    sos = signal.butter(4, band, btype="bandpass", fs=fs, output="sos")
    envelope = np.abs(signal.hilbert(signal.sosfiltfilt(sos, np.asarray(x, dtype=float))))
    envelope -= envelope.mean()
    window = signal.windows.flattop(envelope.size, sym=False)
    amp = 2 * np.abs(np.fft.rfft(envelope * window)) / window.sum()
    freq = np.fft.rfftfreq(envelope.size, 1 / fs)
    enbw = enbw_lines(window)
    return Spectrum(
        freq,
        amp,
        "gE",
        f"envelope (Hilbert) of {band[0]:.0f}-{band[1]:.0f} Hz band, one-sided peak amplitude",
        "flat-top",
        enbw * fs / envelope.size,
        enbw,
    )


def velocity_spectrum(
    x: np.ndarray,
    fs: float,
    band: tuple[float, float] = (10.0, 1000.0),
    seconds: float = 2.0,
    bandwidth_hz: float | None = None,
) -> Spectrum:
    """Velocity r.m.s. per line in mm/s over ``band``, from acceleration ``x`` in g.

    Welch power spectrum (scaling "spectrum": a sine on a line reads its mean
    square), Hann window of ``seconds``, 50 % overlap; each line divided by
    2 pi f. ``overall`` is the band's V_RMS: the root of the sum of the lines'
    mean squares divided by Hann's ENBW of 1.5 lines (each line also holds the
    power of its neighbours' within the window's noise bandwidth).

    The band's top is clipped to the Nyquist frequency and to ``bandwidth_hz``
    (the chain's, :func:`chain_bandwidth`), and ``note`` names both bands. A
    low edge that lies fewer than :data:`LOW_EDGE_LINES` lines above 0 Hz (a
    2 Hz edge needs segments of 2 s) is refused: the record is too short.
    """
    nperseg = min(int(seconds * fs), len(x))
    spacing = fs / nperseg
    if band[0] < LOW_EDGE_LINES * spacing:
        need = LOW_EDGE_LINES / band[0]
        raise SDTError(
            f"a velocity spectrum from {band[0]:g} Hz needs segments of at least {need:g} s "
            f"({LOW_EDGE_LINES} lines below the band's low edge); these have "
            f"{nperseg / fs:.3g} s: give a longer record (or seconds=) or a band from "
            f"{LOW_EDGE_LINES * spacing:.3g} Hz"
        )
    top = min(band[1], fs / 2, bandwidth_hz or np.inf)
    note = ""
    if top < band[1]:
        why = "the chain's bandwidth" if top == bandwidth_hz else "the Nyquist frequency"
        note = f"{band[0]:g}-{top:.4g} Hz, not {band[0]:g}-{band[1]:g} Hz: {why} is {top:.4g} Hz"
    freq, power = signal.welch(x, fs=fs, window="hann", nperseg=nperseg, scaling="spectrum")
    keep = (freq >= band[0]) & (freq <= top)
    velocity = np.sqrt(power[keep]) * G_N * 1e3 / (2 * np.pi * freq[keep])
    enbw = enbw_lines(signal.windows.hann(nperseg, sym=False))
    return Spectrum(
        freq[keep],
        velocity,
        "mm/s r.m.s.",
        "velocity r.m.s. per line (Welch power spectrum / 2 pi f), 50 % overlap",
        "Hann",
        enbw * spacing,
        enbw,
        overall=float(np.sqrt(np.sum(velocity**2) / enbw)),
        band_hz=(float(band[0]), float(top)),
        note=note,
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
        1.5 * fs / nperseg,
    )
