"""The paper's 8-value edge feature vector (paper section 2.3, eq. 5-6; SPEC section 3).

{sigma, S, K, CF, A_RMS, A_Peak, V_RMS, D_RMS}: four broadband time-domain
statistics and four narrowband spectral kinematics, 32 bytes per axis in
float32. Computed on a whole batch of windows at once: moments on the
(n_windows, n_samples) matrix and one batched real FFT.
"""

from __future__ import annotations

import numpy as np

from sdt_framework import FeatureSetSpec, hookimpl

G = 9.80665  # m/s^2 per g
BAND_ACC_LOW_HZ = 10.0
BAND_KIN_HZ = (10.0, 1000.0)


def compute(windows: np.ndarray, fs: float) -> np.ndarray:
    """Eight features per window.

    Parameters
    ----------
    windows
        Acceleration in g, shape (n_windows, n_samples).
    fs
        Sampling rate, Hz.

    Returns
    -------
    numpy.ndarray
        float32, shape (n_windows, 8): sigma [g], S [-], K [-] (Pearson, normal
        = 3), CF [-], A_RMS [g], A_Peak [g], V_RMS [mm/s], D_RMS [um]. A
        constant window has S = 0, K = 0 and CF = 0 (no variation to describe).
    """
    x = np.asarray(windows, dtype=np.float64)
    n = x.shape[1]
    xc = x - x.mean(axis=1, keepdims=True)

    m2 = np.mean(xc**2, axis=1)
    m3 = np.mean(xc**3, axis=1)
    m4 = np.mean(xc**4, axis=1)
    flat = m2 <= 0
    safe_m2 = np.where(flat, 1.0, m2)
    sigma = np.sqrt(m2)
    skew = np.where(flat, 0.0, m3 / safe_m2**1.5)
    kurt = np.where(flat, 0.0, m4 / safe_m2**2)
    crest = np.where(flat, 0.0, np.max(np.abs(xc), axis=1) / np.sqrt(safe_m2))

    amp = 2.0 * np.abs(np.fft.rfft(xc, axis=1)) / n
    freqs = np.fft.rfftfreq(n, d=1.0 / fs)
    acc_band = (freqs >= BAND_ACC_LOW_HZ) & (freqs <= fs / 2)
    a_band = amp[:, acc_band]
    a_rms = np.sqrt(np.sum(a_band**2, axis=1) / 2)
    a_peak = a_band.max(axis=1) if a_band.shape[1] else np.zeros(len(x))

    kin = (freqs >= BAND_KIN_HZ[0]) & (freqs <= BAND_KIN_HZ[1])
    omega = 2 * np.pi * freqs[kin]
    acc_ms2 = amp[:, kin] * G
    v_rms = np.sqrt(np.sum((acc_ms2 / omega) ** 2, axis=1) / 2) * 1e3
    d_rms = np.sqrt(np.sum((acc_ms2 / omega**2) ** 2, axis=1) / 2) * 1e6

    return np.column_stack([sigma, skew, kurt, crest, a_rms, a_peak, v_rms, d_rms]).astype(
        np.float32
    )


PAPER8 = FeatureSetSpec(
    name="paper8",
    description="Paper eq. 6: sigma, skewness, kurtosis, crest factor, A_RMS, A_Peak, V_RMS, D_RMS",
    source="Paper section 2.3, eq. 5-6; ISO 10816-7 band 10-1000 Hz for V_RMS and D_RMS",
    feature_names=("sigma", "S", "K", "CF", "A_RMS", "A_Peak", "V_RMS", "D_RMS"),
    units=("g", "1", "1", "1", "g", "g", "mm/s", "um"),
    compute=compute,
)


@hookimpl
def register_features(register):
    """Register the `paper8` feature set."""
    register(PAPER8)
