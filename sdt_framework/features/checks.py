"""The checks feature extraction runs once, for every feature set (STYLE item 7).

Before compute: the signal holds real, finite numbers in 1 or 2 dimensions, and
every frequency band the feature set declares (:class:`~sdt_framework.specs.FeatureBand`)
holds at least one FFT bin of a window at the given rate (SPEC section 3: paper8's
spectrum runs from 10 Hz to Nyquist and its V_RMS, D_RMS from 10 to 1000 Hz; at
fs = 15 Hz both are empty and the features would silently be 0). After compute:
shape (n_windows, n_features), numeric, finite, cast to float32. A set working
in orders of the running speed gets the same check for its order bands at the
recording's speed (:func:`check_order_bands`): a band above the Nyquist frequency
of the rate, or holding no FFT bin, is refused naming the band, its order, the
speed and where the rate comes from.
"""

from __future__ import annotations

import numpy as np

from ..arguments import real_array
from ..errors import SDTError
from ..specs import FeatureContext, FeatureSetSpec

__all__ = ["check_bands", "check_feature_output", "check_order_bands", "check_signal"]


def check_signal(x: object) -> np.ndarray:
    """``x`` as an array of 1 or 2 dimensions of real, finite numbers, or raise.

    Raises
    ------
    ArgumentTypeError
        Booleans, complex numbers, Python objects or text (also a TypeError).
    SDTError
        Wrong dimensions, or a NaN/inf (its position is named).
    """
    array = real_array(x, "x")
    if array.ndim not in (1, 2):
        raise SDTError(
            f"expected a 1-D signal or a 2-D array (acquisitions x samples), got "
            f"{array.ndim}-D shape {array.shape}"
        )
    finite = np.isfinite(array)
    if not finite.all():
        index = tuple(int(i) for i in np.argwhere(~finite)[0])
        where = (
            f"sample {index[0]}"
            if array.ndim == 1
            else f"acquisition {index[0]}, sample {index[1]}"
        )
        raise SDTError(f"signal has a non-finite value {float(array[index])!r} at {where}")
    return array


#: where a rate comes from, when the caller does not say: the command's option
RATE_GIVEN = "the sampling rate given (--fs)"


def check_bands(
    spec: FeatureSetSpec, fs: float, window_length: int, rate_from: str = RATE_GIVEN
) -> None:
    """Refuse a rate at which a band of ``spec`` holds no FFT bin of a window; ``rate_from``
    says where the rate came from (an option, a file's header, a sensor's output rate).

    The bins are those of a real FFT of ``window_length`` samples at ``fs``
    (k fs / N, 0 <= k <= N/2); a band [low, high] keeps the bins with
    low <= f_k <= min(high, fs/2), both edges inclusive like paper8's sums.

    Raises
    ------
    SDTError
        Naming the feature set, the band, its features, the rate and its Nyquist.
    """
    if not spec.bands:
        return
    freqs = np.fft.rfftfreq(window_length, d=1.0 / fs)
    for band in spec.bands:
        high = freqs[-1] if band.high_hz is None else band.high_hz
        if np.any((freqs >= band.low_hz) & (freqs <= high)):
            continue
        if freqs[-1] < band.low_hz:
            fix = f"the rate must be above about 2 x {band.low_hz:g} = {2 * band.low_hz:g} Hz"
        else:
            fix = f"no bin falls inside it ({fs / window_length:g} Hz apart): use longer windows"
        raise SDTError(
            f"feature set {spec.name!r}: the band {band.describe()} of "
            f"{', '.join(band.features)} holds no FFT bin at fs={fs:g} Hz (Nyquist {fs / 2:g} Hz, "
            f"{window_length}-sample windows), so those features would be 0; {fix} "
            f"(docs/features.md, Windows); check {rate_from}"
        )


def check_order_bands(
    spec: FeatureSetSpec,
    fs: float,
    window_length: int,
    context: FeatureContext | None,
    rate_from: str = RATE_GIVEN,
) -> None:
    """Refuse a set needing the speed without one, and an order band the rate cannot hold.

    At ``context.speed_hz`` each band of ``spec.order_bands(context)`` spans
    [low, high] x speed Hz: it must end at or below the Nyquist frequency fs/2
    (a band of the envelope of the carrier band [c, fs/2]: at or below its
    width fs/2 - c) and hold at least one bin of a real FFT of ``window_length``
    samples.

    Raises
    ------
    SDTError
        No context for a set that needs one; a band above Nyquist or without a
        bin (naming the band, its order, the speed, the rate and ``rate_from``).
    """
    if not spec.needs_speed:
        return
    if context is None:
        raise SDTError(
            f"feature set {spec.name!r} works in orders of the running speed and needs the "
            f"recording's speed: give context=FeatureContext(speed_hz=..., machine=...) "
            f"(sdt_framework.specs), or run it in a benchmark, which hands each recording's "
            f"speed down (docs/features.md, Order-domain features)"
        )
    if spec.order_bands is None:
        return
    nyquist = fs / 2
    spacing = fs / window_length
    for band in spec.order_bands(context):
        low, high = band.edges_hz(context.speed_hz)
        at = f"at {context.describe_speed()}"
        if high > nyquist:
            raise SDTError(
                f"feature set {spec.name!r}: order band {band.describe()} {at} reaches "
                f"{high:.4g} Hz, above the Nyquist frequency {nyquist:g} Hz of fs={fs:g} Hz "
                f"({rate_from}); a rate above {2 * high:.4g} Hz keeps it, or use a feature set "
                f"without this band"
            )
        carrier = band.carrier_low_hz
        if carrier is not None and high > nyquist - carrier:
            raise SDTError(
                f"feature set {spec.name!r}: envelope band {band.describe()} {at} reaches "
                f"{high:.4g} Hz, above {max(nyquist - carrier, 0):.4g} Hz, the width of its "
                f"carrier band {carrier:g} Hz to Nyquist at fs={fs:g} Hz ({rate_from}): the "
                f"envelope holds no modulation faster than that; a rate above "
                f"{2 * (carrier + high):.4g} Hz keeps it, or use a feature set without this band"
            )
        first = np.ceil(low / spacing - 1e-9)
        if first * spacing > high + 1e-9:
            raise SDTError(
                f"feature set {spec.name!r}: order band {band.describe()} {at} spans "
                f"{low:.4g}-{high:.4g} Hz and holds no FFT bin of a {window_length}-sample "
                f"window ({spacing:g} Hz apart); use longer windows (--window-s) or check the "
                f"speed"
            )


def check_feature_output(values: object, n_windows: int, spec: FeatureSetSpec) -> np.ndarray:
    """Validate a compute result and return it as float32.

    Parameters
    ----------
    values
        What ``spec.compute`` returned.
    n_windows
        Number of windows it was given.
    spec
        The feature set, named in every error.

    Raises
    ------
    SDTError
        Non-numeric values, a shape other than (n_windows, n_features), or a
        non-finite value (the message names the feature and the window).
    """
    where = f"feature set {spec.name!r} ({', '.join(spec.feature_names)})"
    try:
        array = np.asarray(values)
    except (TypeError, ValueError) as exc:
        raise SDTError(
            f"{where}: compute returned something that is not an array ({exc})"
        ) from None
    if array.dtype.kind not in "fiu":
        raise SDTError(
            f"{where}: compute returned dtype {array.dtype} ({type(values).__name__}); "
            f"expected real numbers (float32, or float64 which is cast)"
        )
    expected = (n_windows, len(spec.feature_names))
    if array.shape != expected:
        raise SDTError(
            f"{where}: compute returned shape {array.shape}, expected {expected} "
            f"(n_windows, n_features)"
        )
    with np.errstate(over="ignore", invalid="ignore"):
        out = array.astype(np.float32, copy=False)
    bad = ~np.isfinite(out)
    if bad.any():
        row, col = (int(i) for i in np.argwhere(bad)[0])
        raise SDTError(
            f"{where}: feature {spec.feature_names[col]!r} is {float(array[row, col])!r} in window "
            f"{row} (not finite in float32); {int(bad.sum())} bad value(s) in total"
        )
    return out
