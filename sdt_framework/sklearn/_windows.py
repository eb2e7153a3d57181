"""Cut long acquisitions into one-window rows, with the groups for ``GroupKFold``."""

from __future__ import annotations

import numpy as np

from sdt_framework.errors import SDTError
from sdt_framework.features import SETTLE_S, WINDOW_S, samples_for

__all__ = ["window_rows"]


def window_rows(
    X,
    fs: float,
    *,
    groups=None,
    window_s: float = WINDOW_S,
    settle_s: float = SETTLE_S,
) -> tuple[np.ndarray, np.ndarray]:
    """One row per analysis window, each with a lead-in, and the group of each row.

    Window k of an acquisition is the one :func:`sdt_framework.features.cut_windows`
    cuts: samples ``[S + k L, S + (k + 1) L)`` with S = round(settle_s fs) and
    L = round(window_s fs), k = 0 .. floor((N - S) / L) - 1. Its row holds the S
    samples before it too, ``[k L, S + (k + 1) L)``: a :class:`SensorTwin` with
    the same ``settle_s`` runs its filters through that lead-in and drops it,
    so each output row covers window k on the sensor's sampling grid, and a
    :class:`FeatureExtractor` turns it into one feature row. Rows overlap by S
    samples (the lead-in is the previous window's tail).

    Parameters
    ----------
    X
        One acquisition (1-D) or several (2-D, one per row), at ``fs`` Hz.
    fs
        Sampling rate, Hz.
    groups
        One label per acquisition (e.g. the physical run it belongs to);
        default: the acquisition's index. Windows of one group must never be
        split between training and test: pass the returned ``row_groups`` to
        ``GroupKFold``.
    window_s, settle_s
        Window length and settling interval, s (SPEC: 0.64 and 0.1).

    Returns
    -------
    rows : numpy.ndarray
        Shape (n_windows, S + L), acquisition order then time order (a copy).
    row_groups : numpy.ndarray
        Shape (n_windows,): the group of each row's acquisition.
    """
    x = np.asarray(X)
    if x.ndim == 1:
        x = x[np.newaxis, :]
    if x.ndim != 2:
        raise SDTError(f"expected 1-D or 2-D acquisitions, got shape {x.shape}")
    if not (np.isfinite(fs) and fs > 0):
        raise SDTError(f"sampling rate must be a positive number of Hz, got {fs!r}")
    length, settle = samples_for(window_s, fs), samples_for(settle_s, fs)
    if length < 1 or settle < 0:
        raise SDTError(f"window_s={window_s!r} and settle_s={settle_s!r} give no window")
    labels = np.arange(x.shape[0]) if groups is None else np.asarray(groups)
    if labels.shape != (x.shape[0],):
        raise SDTError(f"{labels.size} groups for {x.shape[0]} acquisitions; give one each")
    per_acq = max(x.shape[1] - settle, 0) // length
    if per_acq == 0:
        raise SDTError(
            f"acquisitions of {x.shape[1]} samples are too short: one window at {fs:g} Hz "
            f"needs {settle + length} samples ({settle} lead-in + {length} window)"
        )
    views = np.lib.stride_tricks.sliding_window_view(x, settle + length, axis=1)
    rows = views[:, : per_acq * length : length].reshape(-1, settle + length).copy()
    return rows, np.repeat(labels, per_acq)
