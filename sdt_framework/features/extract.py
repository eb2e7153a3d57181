"""Feature extraction: validate once in the framework, compute in the plugin.

:class:`FeatureExtractor` is the template method of STYLE item 7. Its public
:meth:`~FeatureExtractor.extract` checks the signal (1-D or 2-D, real, finite,
long enough for one window), cuts the windows, mean-centres every window and
only then calls the feature set's small ``compute(windows, fs)``. It checks
what comes back (shape (n_windows, n_features), numeric, finite) and casts it
to float32, so a plugin never repeats those checks and every feature, built-in
or user-written, sees the same centred windows (SPEC section 3: "each window is
mean-centred first"; a compute that centres again, like ``paper8``, is
unaffected).
"""

from __future__ import annotations

import numpy as np

from ..errors import SDTError
from ..specs import FeatureSetSpec
from .table import FeatureTable
from .windowing import SETTLE_S, WINDOW_S, cut_windows

__all__ = ["FeatureExtractor", "check_feature_output", "extract"]


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


def _check_signal(x: object) -> np.ndarray:
    array = np.asarray(x)
    if array.ndim not in (1, 2):
        raise SDTError(
            f"expected a 1-D signal or a 2-D array (acquisitions x samples), got "
            f"{array.ndim}-D shape {array.shape}"
        )
    if array.dtype.kind not in "fiu":
        raise SDTError(f"signal must be real numbers, got dtype {array.dtype}")
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


class FeatureExtractor:
    """Extract one feature set from signals, with all checks done here once.

    Parameters
    ----------
    feature_set
        The feature set (a registered or composed :class:`FeatureSetSpec`).
    window_s, settle_s
        Window length and settling interval, seconds (SPEC: 0.64 and 0.1).
    """

    def __init__(
        self, feature_set: FeatureSetSpec, *, window_s: float = WINDOW_S, settle_s: float = SETTLE_S
    ) -> None:
        self.feature_set = feature_set
        self.window_s = window_s
        self.settle_s = settle_s

    def _compute(self, windows: np.ndarray, fs: float) -> object:
        """The domain part: the feature set's compute on centred float64 windows."""
        return self.feature_set.compute(windows, fs)

    def extract(self, x: np.ndarray, fs: float) -> FeatureTable:
        """Features of every window of ``x``.

        Parameters
        ----------
        x
            One acquisition (1-D) or several (2-D, one per row), in the
            feature set's input unit (g for ``paper8``), sampled at ``fs``.
        fs
            Sampling rate, Hz.

        Returns
        -------
        FeatureTable
            float32 values, one row per window, with names, units and indices.
        """
        signal = _check_signal(x)
        cut = cut_windows(signal, fs, window_s=self.window_s, settle_s=self.settle_s)
        # One vectorised pass: float64 copy, each window minus its own mean.
        centred = cut.data - cut.data.mean(axis=1, keepdims=True, dtype=np.float64)
        try:
            raw = self._compute(centred, float(fs))
        except SDTError:
            raise
        except Exception as exc:
            exc.add_note(f"while computing feature set {self.feature_set.name!r}")
            raise
        values = check_feature_output(raw, cut.n_windows, self.feature_set)
        return FeatureTable(
            values=values,
            names=tuple(self.feature_set.feature_names),
            units=tuple(self.feature_set.units),
            acquisition=cut.acquisition,
            window=cut.window,
            feature_set=self.feature_set.name,
            fs=float(fs),
            window_length=cut.length,
            settle=cut.settle,
        )


def extract(
    x: np.ndarray,
    fs: float,
    feature_set: FeatureSetSpec,
    *,
    window_s: float = WINDOW_S,
    settle_s: float = SETTLE_S,
) -> FeatureTable:
    """Extract ``feature_set`` from every window of ``x``; see :class:`FeatureExtractor`.

    Examples
    --------
    >>> table = extract(signal_g, 3200.0, registry.feature_set("paper8"))  # doctest: +SKIP
    >>> table.to_frame().head()  # doctest: +SKIP
    """
    return FeatureExtractor(feature_set, window_s=window_s, settle_s=settle_s).extract(x, fs)
