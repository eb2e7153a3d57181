"""Order-domain features: the paper's kinematics in orders of the running speed (issue 43).

A line that moves with the shaft (1x, 2x, bearing defect rates) sits at a fixed
*order* (multiple of the running speed) while its frequency in Hz moves with
speed; fixed-Hz features such as paper8's bands see it move in and out of their
bands, order features do not. Every band here is in orders, read at the speed
of the recording the windows come from (the :class:`FeatureContext` the
framework hands down: given by the dataset, or an estimate read off the
spectrum, named as such in the features' metadata).

Columns (docs/features.md, "Order-domain features", has the arithmetic):

- ``A_1X``, ``A_2X``, ``A_3X`` [g]: acceleration RMS in 1x, 2x, 3x +- 0.25 order;
- ``V_ORD`` [mm/s], ``D_ORD`` [um]: velocity and displacement RMS over 0.4-40
  orders, paper8's V_RMS and D_RMS band (10-1000 Hz) at the paper's Motor-2
  speed (1480 rpm: 0.41-40.5 orders) carried over to orders;
- ``ENV_1X``, ``ENV_BPFO``, ``ENV_BPFI``, ``ENV_BSF`` [g]: the envelope of the
  signal above 500 Hz (to Nyquist), its spectrum read in orders: at 1x, and the
  first three harmonics of BPFO, BPFI and 2 x BSF (a ball defect meets both
  races once per spin revolution) of the bearing nearest the channel.

Not here: vane pass (no source gives the rig pump's vane count: the synthetic
pump's 6 is kept without one, docs/data.md) and FTF (about 0.4 order: a 0.64 s
window resolves 1.56 Hz, 0.13 order at 740 rpm, too coarse to part it from 1x
and 0 with +-0.25-order bands).

One batched real FFT of the Hann-windowed windows gives the spectrum bands;
the envelope is the magnitude of the analytic signal of the carrier band (one
inverse FFT of the same batch) and one more batched FFT gives its spectrum.
Band sums are one matrix product each: no loop over windows.
"""

from __future__ import annotations

import numpy as np

from sdt_framework import FeatureSetSpec, hookimpl
from sdt_framework.errors import SDTError
from sdt_framework.hookspecs import Register
from sdt_framework.specs import BearingSpec, FeatureBand, FeatureContext, OrderBand

G = 9.80665  # m/s^2 per g
#: half width of a shaft-order band, orders: 2 FFT lines of a 0.64 s window at 740 rpm (a choice)
HALF_WIDTH = 0.25
#: bearing bands widen by this share of their order: rolling elements slide as well as roll,
#: so the kinematic defect rate is approximate (a stated allowance, not a sourced figure)
SLIP = 0.02
HARMONICS = 3
#: paper8's 10-1000 Hz V_RMS / D_RMS band at 1480 rpm (24.67 Hz), in orders
KIN_ORDERS = (0.4, 40.0)
#: lower edge of the envelope's carrier band, Hz (a resonance does not move with speed)
CARRIER_LOW_HZ = 500.0

SPECTRUM = ("A_1X", "A_2X", "A_3X", "V_ORD", "D_ORD")
ENVELOPE = ("ENV_1X", "ENV_BPFO", "ENV_BPFI", "ENV_BSF")


def bearing_of(context: FeatureContext) -> tuple[BearingSpec, str]:
    """The bearing whose defect orders are read, and why it: the one listed at the
    recording's channel, else the machine's first."""
    machine = context.machine
    where = f"recording {context.recording!r}" if context.recording else "the recording"
    if machine is None:
        raise SDTError(
            f"feature set 'orders' reads the bearing defect orders of {where}'s machine, and no "
            f"machine spec is given for it; describe it in machines.toml beside the manifest "
            f"or [benchmark] machine_specs (docs/severity.md, 'Your machine')"
        )
    if not machine.bearings:
        raise SDTError(
            f"machine {machine.name!r} lists no bearings, so feature set 'orders' has no bearing "
            f"defect orders for {where}; add its bearings with their geometry (docs/severity.md, "
            f"'Your machine') or select machines that list them"
        )
    for bearing in machine.bearings:
        if bearing.channel == context.channel:
            return bearing, f"bearing {bearing.name} at {bearing.channel}"
    first = machine.bearings[0]
    return first, f"bearing {first.name} ({machine.name}'s first; none listed at the channel)"


def order_bands(context: FeatureContext) -> tuple[OrderBand, ...]:
    """Every band the features read, in orders, at ``context`` (its machine's bearing)."""
    bearing, which = bearing_of(context)
    low, high = KIN_ORDERS
    bands = [
        OrderBand(name=f"{k}x", features=(f"A_{k}X",), order=k, half_width=HALF_WIDTH)
        for k in (1, 2, 3)
    ]
    bands.append(
        OrderBand(
            name=f"{low:g}-{high:g} orders", features=("V_ORD", "D_ORD"),
            order=(low + high) / 2, half_width=(high - low) / 2,
        )
    )  # fmt: skip
    bands.append(
        OrderBand(
            name="envelope 1x", features=("ENV_1X",), order=1.0, half_width=HALF_WIDTH,
            carrier_low_hz=CARRIER_LOW_HZ,
        )
    )  # fmt: skip
    rates = {"BPFO": bearing.bpfo, "BPFI": bearing.bpfi, "BSF": 2 * bearing.bsf}
    for label, rate in rates.items():
        base = f"2 x BSF {bearing.bsf:.4g}" if label == "BSF" else f"{label} {rate:.4g}"
        for k in range(1, HARMONICS + 1):
            bands.append(
                OrderBand(
                    name=f"{label} x{2 * k if label == 'BSF' else k}",
                    features=(f"ENV_{label}",), order=k * rate,
                    half_width=HALF_WIDTH + SLIP * k * rate,
                    derivation=f"{k} x {base} of {which}", carrier_low_hz=CARRIER_LOW_HZ,
                )
            )  # fmt: skip
    return tuple(bands)


def _weights(
    bands: tuple[OrderBand, ...], names: tuple[str, ...], orders: np.ndarray
) -> np.ndarray:
    """(len(names), n_bins): 1 on the lines of the union of each feature's bands, else 0."""
    out = np.zeros((len(names), orders.size))
    for band in bands:
        inside = (orders >= band.low) & (orders <= band.high)
        for name in band.features:
            if name in names:
                out[names.index(name)] = np.maximum(out[names.index(name)], inside)
    return out


def _mean_square(x: np.ndarray, window: np.ndarray, per_bin: np.ndarray) -> np.ndarray:
    """Mean square of each one-sided line of each row of ``x`` (Hann-windowed), g^2."""
    import scipy.fft

    spectrum = scipy.fft.rfft(x * window, axis=1, workers=-1)
    return (spectrum.real**2 + spectrum.imag**2) * per_bin


def compute(windows: np.ndarray, fs: float, context: FeatureContext) -> np.ndarray:
    """Nine order-domain features per window, for a whole batch at once.

    Parameters
    ----------
    windows
        Acceleration in g, shape (n_windows, n_samples); centred here too.
    fs
        Sampling rate, Hz.
    context
        The recording's running speed and machine (its bearing's defect orders).

    Returns
    -------
    numpy.ndarray
        float32 (n_windows, 9): A_1X, A_2X, A_3X [g], V_ORD [mm/s], D_ORD [um],
        ENV_1X, ENV_BPFO, ENV_BPFI, ENV_BSF [g].

    Notes
    -----
    With w the periodic Hann window and X_k the FFT of w x, line k holds the
    mean square c_k |X_k|^2 / (N sum w^2), c_k = 2 (1 at DC and Nyquist): for a
    line of amplitude a well inside a band, the band's sum is a^2/2 (Parseval).
    A feature is the square root of its band's sum, velocity and displacement
    weighting each line by (g / 2 pi f_k)^2 and (g / (2 pi f_k)^2)^2. The
    envelope is |z| - mean |z|, z the analytic signal of the lines from 500 Hz
    to Nyquist (2 X_k there, 0 elsewhere, inverse FFT).
    """
    import scipy.fft
    from scipy.signal import windows as tapers

    x = np.asarray(windows, dtype=np.float64)
    x = x - x.mean(axis=1, keepdims=True)
    n = x.shape[1]
    bands = order_bands(context)
    freqs = np.fft.rfftfreq(n, d=1.0 / fs)
    orders = freqs / context.speed_hz
    window = tapers.hann(n, sym=False)
    sides = np.full(freqs.size, 2.0)
    sides[0] = 0.0  # DC: the windows are centred
    if n % 2 == 0:
        sides[-1] = 1.0
    per_bin = sides / (n * np.sum(window**2))

    spectrum = _weights(bands, SPECTRUM, orders)
    omega = np.where(freqs > 0, 2 * np.pi * freqs, np.inf)
    spectrum[3] *= (G * 1e3 / omega) ** 2  # mm/s
    spectrum[4] *= (G * 1e6 / omega**2) ** 2  # um
    values = np.sqrt(_mean_square(x, window, per_bin) @ spectrum.T)

    carrier = np.where(freqs >= CARRIER_LOW_HZ, sides, 0.0)  # 2 X_k (X_{N/2} once), 0 below
    analytic = scipy.fft.ifft(scipy.fft.rfft(x, axis=1) * carrier, n=n, axis=1, workers=-1)
    envelope = np.abs(analytic)
    del analytic
    envelope -= envelope.mean(axis=1, keepdims=True)
    env_values = np.sqrt(
        _mean_square(envelope, window, per_bin) @ _weights(bands, ENVELOPE, orders).T
    )
    return np.column_stack([values, env_values]).astype(np.float32)


ORDERS = FeatureSetSpec(
    name="orders",
    description="Orders of the running speed: A at 1x/2x/3x, V and D over 0.4-40 orders, "
    "envelope at 1x and the bearing's BPFO, BPFI, 2xBSF",
    source="docs/features.md, 'Order-domain features' (issue 43); bearing orders from the "
    "machine spec (docs/severity.md); bands in orders are this set's stated choices",
    feature_names=(*SPECTRUM, *ENVELOPE),
    units=("g", "g", "g", "mm/s", "um", "g", "g", "g", "g"),
    compute=compute,
    bands=(FeatureBand(features=ENVELOPE, low_hz=CARRIER_LOW_HZ),),
    needs_speed=True,
    order_bands=order_bands,
    node_ffts=3,  # spectrum; the analytic signal (inverse); the envelope's spectrum
)


@hookimpl
def register_features(register: Register) -> None:
    """Register the `orders` feature set."""
    register(ORDERS)
