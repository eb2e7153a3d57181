"""``SensorTwin``: the SDT measurement chain as a scikit-learn transformer."""

from __future__ import annotations

import math

import numpy as np
from sklearn.base import BaseEstimator, ClassNamePrefixFeaturesOutMixin, TransformerMixin
from sklearn.utils.validation import check_is_fitted, validate_data

from sdt_framework.api import resolve
from sdt_framework.arguments import check_rate, check_real, check_seed
from sdt_framework.chain import compile_chain, degrade
from sdt_framework.chain.stages import sample_count
from sdt_framework.errors import ArgumentValueError, SDTError
from sdt_framework.features import samples_for
from sdt_framework.specs import SensorSpec

__all__ = ["SensorTwin", "row_noise_ids"]

_HASH_SEED = 0x5D7_5EED


def row_noise_ids(X: np.ndarray) -> list[int]:
    """A 64-bit fingerprint of each row's samples: the row's noise id in :class:`SensorTwin`.

    A universal hash of the float64 bit patterns (sum of bits x fixed odd
    weights, modulo 2**64), computed for all rows at once. The same samples
    always give the same id, whatever the batch or the row's position in it.
    """
    bits = np.ascontiguousarray(X, dtype=np.float64).view(np.uint64)
    weights = np.random.default_rng(_HASH_SEED).integers(
        0, 2**63, size=bits.shape[1], dtype=np.uint64
    ) * np.uint64(2) + np.uint64(1)
    return (bits * weights).sum(axis=1, dtype=np.uint64).tolist()


def _resolve_sensor(sensor: str | SensorSpec) -> SensorSpec:
    """The profile (its listed stages bound in the default registry), or the named one."""
    return resolve(SensorSpec, sensor if isinstance(sensor, SensorSpec) else str(sensor), "sensor")


class SensorTwin(ClassNamePrefixFeaturesOutMixin, TransformerMixin, BaseEstimator):
    """What a sensor would have recorded of each row: the Sensor Digital Twin.

    Each input row is one continuous stretch of a reference signal in g at
    ``fs`` Hz (a whole acquisition, or a window with a lead-in cut by
    :func:`window_rows`); each output row is the degraded signal at the
    sensor's rate, with its first ``settle_s`` seconds (the filters' start-up
    transient) removed. Output shape (n_rows, M), M = floor((N - 1) F_sensor /
    fs) + 1 - round(settle_s F_sensor); after :meth:`fit`, ``fs_out_`` holds
    F_sensor, the ``fs`` to give the next step.

    Parameters
    ----------
    sensor
        Registered sensor name (``"adxl345"``) or a :class:`SensorSpec`.
    fs
        Rate of the input rows, Hz.
    seed
        Base seed of the injected noise, an integer (1.7 or True are refused at
        :meth:`fit`, not truncated).
    noise
        False switches the noise stage off.
    settle_s
        Seconds dropped at the start of each output row (SPEC: 0.1).

    Notes
    -----
    The noise of a row is drawn from ``(seed, row_noise_ids(row))``: it depends
    on the row's samples only, so a row gets the same noise in any batch, in any
    order, in ``fit_transform`` and ``transform``, and two sensors see the same
    draws (common random numbers). Identical rows get identical noise.
    Stateless: ``fit`` only checks the data and resolves the sensor.

    Examples
    --------
    >>> twin = SensorTwin("adxl345", fs=20000, seed=0)  # doctest: +SKIP
    >>> twin.fit_transform(rows).shape  # rows: (n, 14800) -> (n, 2048)  # doctest: +SKIP
    """

    def __init__(
        self,
        sensor: str | SensorSpec = "adxl345",
        fs: float = 20000.0,
        seed: int = 0,
        noise: bool = True,
        settle_s: float = 0.1,
    ) -> None:
        self.sensor = sensor
        self.fs = fs
        self.seed = seed
        self.noise = noise
        self.settle_s = settle_s

    def fit(self, X, y=None):
        """Check ``X`` and the parameters; resolve the sensor and the output length."""
        X = validate_data(self, X, dtype=np.float64)
        check_seed(self.seed)  # 1.7 or True refused, not truncated to 1
        check_rate(self.fs)
        spec = _resolve_sensor(self.sensor)
        settle_s = check_real(self.settle_s, "settle_s", "seconds")
        if not (math.isfinite(settle_s) and settle_s >= 0):
            raise ArgumentValueError(f"settle_s must be a finite number >= 0 s, got {settle_s!r}")
        chain = compile_chain(spec, float(self.fs))
        n_out = sample_count(X.shape[1], float(self.fs), chain.fs_out)
        settle = samples_for(self.settle_s, chain.fs_out)
        if n_out - settle < 1:
            raise SDTError(
                f"rows of {X.shape[1]} samples at {self.fs:g} Hz give {n_out} samples at "
                f"{chain.fs_out:g} Hz, none left after settle_s={self.settle_s:g} s "
                f"({settle} samples); use longer rows or a smaller settle_s"
            )
        self.sensor_ = spec
        self.fs_out_ = chain.fs_out
        self.settle_samples_ = settle
        self._n_features_out = n_out - settle
        return self

    def transform(self, X):
        """The degraded rows, shape (n_rows, M), float64 in g at ``fs_out_``."""
        check_is_fitted(self, "sensor_")
        X = validate_data(self, X, dtype=np.float64, reset=False)
        y, _ = degrade(
            X,
            float(self.fs),
            self.sensor_,
            seed=check_seed(self.seed),
            noise=bool(self.noise),
            label="SensorTwin input",
            acquisition_ids=row_noise_ids(X),
        )
        return y[:, self.settle_samples_ :]

    def __sklearn_tags__(self):
        tags = super().__sklearn_tags__()
        tags.transformer_tags.preserves_dtype = ["float64"]
        return tags
