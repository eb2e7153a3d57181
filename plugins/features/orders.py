"""Order-domain features: the paper's kinematics in orders of the running speed (issue 43).

A line that moves with the shaft (1x, 2x, bearing defect rates) sits at a fixed
*order* (multiple of the running speed) while its frequency in Hz moves with
speed; fixed-Hz features such as paper8's bands see it move in and out of their
bands, order features do not. Every band here is in orders, read at the speed
of the recording the windows come from (the :class:`FeatureContext` the
framework hands down: given by the dataset, or an estimate read off the
spectrum, named as such in the features' metadata).

Two sets (docs/features.md, "Order-domain features", has the arithmetic):

``orders``, any machine (it needs only the speed):

- ``A_1X``, ``A_2X``, ``A_3X`` [g]: acceleration RMS in 1x, 2x, 3x +- 0.25 order;
- ``V_ORD`` [mm/s], ``D_ORD`` [um]: velocity and displacement RMS over 0.4-40
  orders, paper8's V_RMS and D_RMS band (10-1000 Hz) at the paper's Motor-2
  speed (1480 rpm: 0.41-40.5 orders) carried over to orders;
- ``ENV_1X`` [g]: the envelope of the signal above 500 Hz (to Nyquist) at 1x.

``bearing-orders``, a machine whose spec lists its bearings: ``ENV_BPFO``,
``ENV_BPFI``, ``ENV_BSF`` [g], the envelope at the first three harmonics of
BPFO, BPFI and 2 x BSF (a ball defect meets both races once per spin
revolution) of the bearing at the channel. Both together: ``orders+bearing-orders``.

Not here: vane pass (no source gives the rig pump's vane count: the synthetic
pump's 6 is kept without one, docs/data.md) and FTF (about 0.4 order: a 0.64 s
window resolves 1.56 Hz, 0.13 order at 740 rpm, too coarse to part it from 1x
and 0 with +-0.25-order bands).
"""

from __future__ import annotations

import numpy as np

from sdt_framework import FeatureSetSpec, hookimpl
from sdt_framework.errors import SDTError
from sdt_framework.hookspecs import Register
from sdt_framework.specs import BearingSpec, FeatureBand, FeatureContext, OrderBand
from sdt_framework.speed import PAD
from sdt_framework.units import G_N as G  # m/s^2 per g

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
BEARING = ("ENV_BPFO", "ENV_BPFI", "ENV_BSF")


def bearing_of(context: FeatureContext) -> tuple[BearingSpec, str]:
    """The bearing whose defect orders are read, and why it: the one listed at the
    recording's channel, else the machine's first."""
    machine = context.machine
    where = f"recording {context.recording!r}" if context.recording else "the recording"
    if machine is None:
        raise SDTError(
            f"feature set 'bearing-orders' reads the bearing defect orders of {where}'s machine, "
            f"and no machine spec is given for it; describe it in machines.toml beside the "
            f"manifest or [benchmark] machine_specs (docs/severity.md, 'Your machine')"
        )
    if not machine.bearings:
        raise SDTError(
            f"machine {machine.name!r} lists no bearings, so feature set 'bearing-orders' has no "
            f"defect orders for {where}; add its bearings with their geometry (docs/severity.md, "
            f"'Your machine'), select machines that list them (--machines), or use 'orders'"
        )
    for bearing in machine.bearings:
        if bearing.channel == context.channel:
            return bearing, f"bearing {bearing.name} at {bearing.channel}"
    first = machine.bearings[0]
    return first, f"bearing {first.name} ({machine.name}'s first; none listed at the channel)"


def shaft_bands(context: FeatureContext) -> tuple[OrderBand, ...]:
    """The bands of the ``orders`` set: 1x, 2x, 3x, 0.4-40 orders, the envelope at 1x."""
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
    return tuple(bands)


def bearing_bands(context: FeatureContext) -> tuple[OrderBand, ...]:
    """The bands of ``bearing-orders``: 3 harmonics of BPFO, BPFI, 2 x BSF in the envelope."""
    bearing, which = bearing_of(context)
    bands = []
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


def hann_lines(spectrum: np.ndarray, n: int) -> np.ndarray:
    """The rfft of the periodic-Hann-windowed rows, from their plain rfft ``spectrum``.

    The periodic Hann window's DFT has three lines: Y_k = X_k / 2 - (X_(k-1) + X_(k+1)) / 4,
    with X_(-1) = conj(X_1) and X_(n/2+1) = conj(X_(n/2-1)) for real rows: the node
    windows in frequency and saves an FFT (one transform gives both spectra).
    """
    left = np.concatenate([spectrum[:, 1:2].conj(), spectrum[:, :-1]], axis=1)
    edge = spectrum[:, -2:-1] if n % 2 == 0 else spectrum[:, -1:]
    right = np.concatenate([spectrum[:, 1:], edge.conj()], axis=1)
    return 0.5 * spectrum - 0.25 * (left + right)


def _power(lines: np.ndarray) -> np.ndarray:
    return lines.real**2 + lines.imag**2


def _features(
    windows: np.ndarray,
    fs: float,
    context: FeatureContext,
    bands: tuple[OrderBand, ...],
    spectrum_names: tuple[str, ...],
    envelope_names: tuple[str, ...],
) -> np.ndarray:
    """The columns ``spectrum_names`` then ``envelope_names`` over ``bands``; see :func:`compute`.

    One rfft of the batch gives both the Hann spectrum (:func:`hann_lines`) and the
    analytic signal of the carrier band (one inverse FFT); one more rfft gives the
    envelope's spectrum. Band sums are one matrix product each: no loop over windows.
    """
    import scipy.fft

    x = np.asarray(windows, dtype=np.float64)
    x = x - x.mean(axis=1, keepdims=True)
    n = x.shape[1]
    freqs = np.fft.rfftfreq(n, d=1.0 / fs)
    orders = freqs / context.speed_hz
    sides = np.full(freqs.size, 2.0)
    sides[0] = 0.0  # DC: the windows are centred
    if n % 2 == 0:
        sides[-1] = 1.0
    per_bin = sides / (n * 0.375 * n)  # N sum w^2; the periodic Hann window: sum w^2 = 3 N / 8
    plain = scipy.fft.rfft(x, axis=1, workers=-1)
    columns = []
    if spectrum_names:
        weights = _weights(bands, spectrum_names, orders)
        omega = np.where(freqs > 0, 2 * np.pi * freqs, np.inf)
        if "V_ORD" in spectrum_names:
            weights[spectrum_names.index("V_ORD")] *= (G * 1e3 / omega) ** 2  # mm/s
        if "D_ORD" in spectrum_names:
            weights[spectrum_names.index("D_ORD")] *= (G * 1e6 / omega**2) ** 2  # um
        columns.append(np.sqrt((_power(hann_lines(plain, n)) * per_bin) @ weights.T))
    if envelope_names:
        carrier = np.where(freqs >= CARRIER_LOW_HZ, sides, 0.0)  # 2 X_k (X_{N/2} once), 0 below
        envelope = np.abs(scipy.fft.ifft(plain * carrier, n=n, axis=1, workers=-1))
        envelope -= envelope.mean(axis=1, keepdims=True)
        lines = hann_lines(scipy.fft.rfft(envelope, axis=1, workers=-1), n)
        weights = _weights(bands, envelope_names, orders)
        columns.append(np.sqrt((_power(lines) * per_bin) @ weights.T))
    return np.column_stack(columns).astype(np.float32)


def compute(windows: np.ndarray, fs: float, context: FeatureContext) -> np.ndarray:
    """Six shaft-order features per window, for a whole batch at once.

    Parameters
    ----------
    windows
        Acceleration in g, shape (n_windows, n_samples); centred here too.
    fs
        Sampling rate, Hz.
    context
        The recording's running speed.

    Returns
    -------
    numpy.ndarray
        float32 (n_windows, 6): A_1X, A_2X, A_3X [g], V_ORD [mm/s], D_ORD [um], ENV_1X [g].

    Notes
    -----
    With w the periodic Hann window and Y_k the FFT of w x, line k holds the
    mean square c_k |Y_k|^2 / (N sum w^2), c_k = 2 (1 at the Nyquist line, 0 at
    DC): for a line of amplitude a well inside a band, the band's sum is a^2/2
    (Parseval), so a feature of a pure line is its RMS, a / sqrt 2. Velocity and
    displacement weight each line by (g / 2 pi f_k)^2 and (g / (2 pi f_k)^2)^2.
    The envelope is |z| - mean |z|, z the analytic signal of the lines from
    500 Hz to Nyquist (2 X_k there, 0 elsewhere, inverse FFT).
    """
    return _features(windows, fs, context, shaft_bands(context), SPECTRUM, ("ENV_1X",))


def compute_bearing(windows: np.ndarray, fs: float, context: FeatureContext) -> np.ndarray:
    """Three envelope features per window at the defect orders of the recording's bearing:
    ENV_BPFO, ENV_BPFI, ENV_BSF [g], each over its first three harmonics (see :func:`compute`)."""
    return _features(windows, fs, context, bearing_bands(context), (), BEARING)


ORDERS = FeatureSetSpec(
    name="orders",
    description="Orders of the running speed: A at 1x/2x/3x, V and D over 0.4-40 orders, "
    "the envelope (500 Hz to Nyquist) at 1x",
    source="docs/features.md, 'Order-domain features' (issue 43); bands in orders are this "
    "set's stated choices",
    feature_names=(*SPECTRUM, "ENV_1X"),
    units=("g", "g", "g", "mm/s", "um", "g"),
    compute=compute,
    bands=(FeatureBand(features=("ENV_1X",), low_hz=CARRIER_LOW_HZ),),
    needs_speed=True,
    order_bands=shaft_bands,
    node_ffts=3,  # the window's spectrum (Hann by the 3-line kernel); the analytic signal
    # (inverse); the envelope's spectrum
    node_speed_pad=PAD,  # a node without a tachometer reads the speed off its spectrum
)

BEARING_ORDERS = FeatureSetSpec(
    name="bearing-orders",
    description="The envelope (500 Hz to Nyquist) at the bearing's BPFO, BPFI, 2xBSF and "
    "their harmonics, in orders of the running speed",
    source="docs/features.md, 'Order-domain features' (issue 43); bearing orders from the "
    "machine spec (docs/severity.md); bands in orders are this set's stated choices",
    feature_names=BEARING,
    units=("g", "g", "g"),
    compute=compute_bearing,
    bands=(FeatureBand(features=BEARING, low_hz=CARRIER_LOW_HZ),),
    needs_speed=True,
    order_bands=bearing_bands,
    node_ffts=3,  # the window's rfft; the analytic signal (inverse); the envelope's rfft
    node_speed_pad=PAD,
)


@hookimpl
def register_features(register: Register) -> None:
    """Register the `orders` and `bearing-orders` feature sets."""
    register(ORDERS)
    register(BEARING_ORDERS)
