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

from ..arguments import check_rate, check_spec
from ..errors import SDTError
from ..specs import FeatureContext, FeatureSetSpec
from .checks import (
    RATE_GIVEN,
    check_bands,
    check_feature_output,
    check_order_bands,
    check_signal,
)
from .table import FeatureTable
from .windowing import SETTLE_S, WINDOW_S, cut_windows

__all__ = ["FeatureExtractor", "check_feature_output", "extract"]


class FeatureExtractor:
    """Extract one feature set from signals, with all checks done here once.

    Parameters
    ----------
    feature_set
        The feature set (a registered or composed :class:`FeatureSetSpec`);
        :func:`sdt_framework.api.extract` also takes its name (``"paper8"``,
        ``"paper8+env_bpfo"``).
    window_s, settle_s
        Window length and settling interval, seconds (SPEC: 0.64 and 0.1).
    """

    def __init__(
        self,
        feature_set: FeatureSetSpec,
        *,
        window_s: float = WINDOW_S,
        settle_s: float = SETTLE_S,
    ) -> None:
        self.feature_set = check_spec(FeatureSetSpec, feature_set, "feature_set")
        self.window_s = window_s
        self.settle_s = settle_s

    def _compute(
        self, windows: np.ndarray, fs: float, context: FeatureContext | None = None
    ) -> object:
        """The domain part: the feature set's compute on centred float64 windows (with the
        recording's context for a set that needs the speed)."""
        if self.feature_set.needs_speed:
            return self.feature_set.compute(windows, fs, context)
        return self.feature_set.compute(windows, fs)

    def extract(
        self,
        x: np.ndarray,
        fs: float,
        *,
        label: str = "",
        rate_from: str = RATE_GIVEN,
        context: FeatureContext | None = None,
    ) -> FeatureTable:
        """Features of every window of ``x``.

        Parameters
        ----------
        x
            One acquisition (1-D) or several (2-D, one per row), in the
            feature set's input unit (g for ``paper8``), sampled at ``fs``;
            real numbers (booleans, complex, objects and text are refused).
        fs
            Sampling rate, Hz.
        label
            The signal's name (its file), put before a message about the signal
            (a NaN, too short for one window, a rate too low for a band) so the
            error names it.
        rate_from
            Where ``fs`` came from, for the message of a rate too low for a band
            (default: the ``--fs`` option).
        context
            The recording's running speed, machine and channel, for a feature
            set that works in orders of the running speed (``needs_speed``);
            ignored by one that does not.

        Returns
        -------
        FeatureTable
            float32 values, one row per window, with names, units and indices.

        Raises
        ------
        ArgumentTypeError
            (a TypeError) ``x`` or ``fs`` of a wrong type.
        SDTError
            A bad signal, or a rate at which a band the feature set declares is
            empty (paper8: 10 Hz to Nyquist, 10-1000 Hz); for a set needing the
            speed: no context, or an order band above Nyquist at that speed.
        """
        fs = check_rate(fs)
        try:
            signal = check_signal(x)
            cut = cut_windows(signal, fs, window_s=self.window_s, settle_s=self.settle_s)
            check_bands(self.feature_set, fs, cut.length, rate_from)
            check_order_bands(self.feature_set, fs, cut.length, context, rate_from)
        except SDTError as exc:
            if not label:
                raise
            raise type(exc)(f"{label}: {exc}") from None
        # One vectorised pass: float64 copy, each window minus its own mean.
        centred = cut.data - cut.data.mean(axis=1, keepdims=True, dtype=np.float64)
        try:
            raw = self._compute(centred, float(fs), context)
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
            speed=context.describe_speed() if context and self.feature_set.needs_speed else "",
        )


def extract(
    x: np.ndarray,
    fs: float,
    feature_set: FeatureSetSpec,
    *,
    window_s: float = WINDOW_S,
    settle_s: float = SETTLE_S,
    label: str = "",
    rate_from: str = RATE_GIVEN,
    context: FeatureContext | None = None,
) -> FeatureTable:
    """Extract ``feature_set`` from every window of ``x``; see :class:`FeatureExtractor`.

    Examples
    --------
    >>> table = extract(signal_g, 3200.0, registry.feature_set("paper8"))  # doctest: +SKIP
    >>> table.to_frame().head()  # doctest: +SKIP
    """
    extractor = FeatureExtractor(feature_set, window_s=window_s, settle_s=settle_s)
    return extractor.extract(x, fs, label=label, rate_from=rate_from, context=context)
