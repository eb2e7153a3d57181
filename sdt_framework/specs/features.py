"""Feature-set specs: the named features a set computes and the bands they need."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, ClassVar, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

from .base import Spec
from .feature_context import FeatureContext, OrderBand

__all__ = ["FeatureBand", "FeatureContext", "FeatureSetSpec", "OrderBand"]

#: bytes per value of each on-node feature dtype
DTYPE_BYTES = {"float16": 2, "float32": 4}


class FeatureBand(BaseModel):
    """A frequency band some features of a set are computed over (SPEC section 3).

    Declared by the feature set, checked by the framework: extraction refuses a
    rate at which the band holds no FFT bin of a window, instead of letting the
    features come out as zeros.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    features: tuple[str, ...] = Field(min_length=1, description="Features computed over it.")
    low_hz: float = Field(ge=0, description="Lower edge, Hz (inclusive).")
    high_hz: float | None = Field(
        default=None, gt=0, description="Upper edge, Hz (inclusive); None: the Nyquist frequency."
    )

    @model_validator(mode="after")
    def _check_edges(self) -> FeatureBand:
        if self.high_hz is not None and self.high_hz <= self.low_hz:
            raise ValueError(f"band {self.describe()}: high_hz must be above low_hz")
        return self

    def describe(self) -> str:
        """The band in words: ``"10-1000 Hz"`` or ``"10 Hz to Nyquist"``."""
        if self.high_hz is None:
            return f"{self.low_hz:g} Hz to Nyquist"
        return f"{self.low_hz:g}-{self.high_hz:g} Hz"


class FeatureSetSpec(Spec):
    """A named set of features computed on a batch of windows.

    ``compute(windows, fs)`` takes a float array (n_windows, window_length) and
    the sampling rate in Hz and returns (n_windows, len(feature_names)). A set
    that works in orders of the running speed sets ``needs_speed`` and is called
    ``compute(windows, fs, context)`` with a :class:`FeatureContext` (the
    recording's speed, machine and channel); its ``order_bands(context)`` lists
    the :class:`OrderBand` s it reads, which the framework checks against the
    rate's Nyquist frequency before compute.
    """

    kind: ClassVar[str] = "feature set"
    _provenance: ClassVar[frozenset[str]] = frozenset({"plugin", "distribution", "compute"})

    feature_names: tuple[str, ...] = Field(min_length=1, description="Column names, in order.")
    units: tuple[str, ...] = Field(min_length=1, description="Unit of each feature, in order.")
    compute: Callable[..., Any] = Field(
        exclude=True, description="compute(windows, fs) -> array (n_windows, n_features)."
    )
    dtype: Literal["float16", "float32"] = Field(
        default="float32",
        description="Type of each value as the node sends it: float32 (4 B) or float16 (2 B).",
    )
    bytes_per_value: int = Field(
        default=4, ge=1, description="Edge payload per value, bytes; follows from dtype."
    )

    bands: tuple[FeatureBand, ...] = Field(
        default=(),
        description="Frequency bands the features need; a rate leaving one empty is refused.",
    )
    needs_speed: bool = Field(
        default=False,
        description="compute(windows, fs, context) takes the recording's FeatureContext.",
    )
    order_bands: Callable[[FeatureContext], tuple[OrderBand, ...]] | None = Field(
        default=None,
        exclude=True,
        description="order_bands(context) -> the OrderBands the features read (needs_speed).",
    )
    node_ffts: int = Field(
        default=1,
        ge=1,
        description="FFTs of the window (its length, per axis) a node computes per report.",
    )
    node_speed_pad: int = Field(
        default=0,
        ge=0,
        description="A node's tachless speed estimate per report: one FFT of this many times "
        "the window's samples (zero-padded), on one axis; 0: none.",
    )

    @model_validator(mode="before")
    @classmethod
    def _bytes_from_dtype(cls, data: Any) -> Any:
        """bytes_per_value follows from dtype (or, given alone, sets it); both must agree."""
        if not isinstance(data, dict):
            return data
        given = data.get("bytes_per_value")
        if data.get("dtype") is None and given is not None:  # a set written before dtype
            by_size = {size: name for name, size in DTYPE_BYTES.items()}
            if given not in by_size:
                raise ValueError(
                    f"bytes_per_value={given!r} matches no dtype; give dtype "
                    f"({', '.join(f'{n}: {b} B' for n, b in DTYPE_BYTES.items())})"
                )
            return {**data, "dtype": by_size[given]}
        dtype = data.get("dtype") or "float32"
        size = DTYPE_BYTES.get(dtype)
        if size is None:
            return data  # the Literal check names the allowed values
        if given is None:
            return {**data, "dtype": dtype, "bytes_per_value": size}
        if given != size:
            raise ValueError(
                f"bytes_per_value={given!r} contradicts dtype={dtype!r} ({size} bytes per "
                f"value); give dtype only"
            )
        return data

    @model_validator(mode="after")
    def _check_lengths(self) -> FeatureSetSpec:
        if len(self.units) != len(self.feature_names):
            raise ValueError(f"{len(self.feature_names)} feature_names but {len(self.units)} units")
        if len(set(self.feature_names)) != len(self.feature_names):
            raise ValueError(f"duplicate feature names in {self.feature_names}")
        for band in self.bands:
            if not set(band.features) <= set(self.feature_names):
                raise ValueError(f"band {band.describe()} names unknown features {band.features}")
        if self.order_bands is not None and not self.needs_speed:
            raise ValueError("order_bands are read at the recording's speed: set needs_speed")
        return self

    @property
    def bytes_per_window(self) -> int:
        """Edge payload of one window of one axis, bytes (paper: 32 B for paper8)."""
        return self.bytes_per_value * len(self.feature_names)

    @property
    def value_dtypes(self) -> tuple[str, ...]:
        """The on-node type of each feature, in column order."""
        return (self.dtype,) * len(self.feature_names)

    def with_dtype(self, dtype: str) -> FeatureSetSpec:
        """A copy whose every value is sent as ``dtype`` ("float16" or "float32")."""
        return self.model_validate({**dict(self), "dtype": dtype, "bytes_per_value": None})

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields plus the compute function's qualified name.

        ``bands``, ``node_ffts`` and ``node_speed_pad`` are left out: they decide which rates are
        refused and what a node's computation costs, not the values computed.
        ``dtype`` is left out: ``bytes_per_value`` follows from it one to one, so
        the hash of a float32 set is the one it had before sets had a dtype;
        ``needs_speed`` is kept only when set, so a set without it hashes as
        before. All keep feature caches and results folders valid.
        """
        data = super().content_dict()
        data.pop("bands", None)
        data.pop("dtype", None)
        data.pop("node_ffts", None)
        data.pop("node_speed_pad", None)
        if not self.needs_speed:
            data.pop("needs_speed", None)
        data["compute"] = f"{self.compute.__module__}:{self.compute.__qualname__}"
        if self.order_bands is not None:
            bands = self.order_bands
            data["order_bands"] = f"{bands.__module__}:{bands.__qualname__}"
        return data
