"""Pydantic v2 specs for everything a plugin can provide.

Specs are frozen and reject unknown fields, so a typo in a TOML sensor file or
a plugin is an error rather than a silently ignored setting. Each spec carries
``plugin`` and ``distribution`` provenance (stamped by the registry, excluded
from the content hash) and a ``source`` reference (datasheet, paper, URL).
"""

from __future__ import annotations

import hashlib
import importlib
import json
import re
from collections.abc import Callable
from typing import Annotated, Any, ClassVar, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from .stage_use import StageUse, Tolerance

__all__ = [
    "ClassifierSpec",
    "DatasetSpec",
    "FeatureBand",
    "FeatureSetSpec",
    "SensorSpec",
    "Spec",
]

_NAME = re.compile(r"^[a-z0-9][a-z0-9._-]*$")
#: a design point's settings after its base name, e.g. ``adxl345~rate=1600,nsd=90``
POINT_SUFFIX = re.compile(r"~[a-z0-9_]+=[a-z0-9.+-]+(,[a-z0-9_]+=[a-z0-9.+-]+)*$")
#: a part's operating mode after its name, e.g. ``adxl355[odr=4000,range=8g]``
MODE_SUFFIX = re.compile(r"\[([a-z0-9_]+=[a-z0-9._+-]+)(,[a-z0-9_]+=[a-z0-9._+-]+)*\]$")

#: rate of a sensor that samples at whatever rate the recording has (the identity reference)
NATIVE = "native"
Axis = Literal["x", "y", "z"]
#: SensorSpec fields that may differ per axis (``SensorSpec.per_axis``)
AXIS_FIELDS = ("noise_density_ug_rthz", "mech_cutoff_hz")
#: annotations of the SensorSpec fields a tolerance may apply to
_NUMERIC = (float, float | None, int, int | None)
#: bytes per value of each on-node feature dtype
DTYPE_BYTES = {"float16": 2, "float32": 4}


class Spec(BaseModel):
    """Common base: a unique lower-case name, a description, provenance."""

    model_config = ConfigDict(frozen=True, extra="forbid", arbitrary_types_allowed=True)

    kind: ClassVar[str] = "spec"
    _provenance: ClassVar[frozenset[str]] = frozenset({"plugin", "distribution"})

    name: str = Field(description="Unique lower-case name used on the command line.")
    description: str = Field(default="", description="One line saying what this is.")
    source: str = Field(default="", description="Datasheet, paper or URL the values come from.")
    plugin: str | None = Field(default=None, description="Plugin that registered it (stamped).")
    distribution: str | None = Field(
        default=None, description="Installed distribution providing it (stamped)."
    )

    @field_validator("name")
    @classmethod
    def _check_name(cls, value: str) -> str:
        if not _NAME.match(value):
            raise ValueError(
                f"{value!r} is not a valid name: use lower-case letters, digits, '.', '_' or '-'"
            )
        return value

    def content_dict(self) -> dict[str, Any]:
        """The fields that define behaviour (provenance excluded), JSON-ready."""
        return self.model_dump(mode="json", exclude=set(self._provenance))

    def content_hash(self) -> str:
        """A stable SHA-256 of the behaviour-defining fields, for cache keys."""
        payload = json.dumps(
            {"kind": self.kind, **self.content_dict()}, sort_keys=True, separators=(",", ":")
        )
        return hashlib.sha256(payload.encode()).hexdigest()


class SensorSpec(Spec):
    """A sensor profile: every parameter of the SDT measurement chain (SPEC section 2).

    A stage whose cutoff is None is not part of the chain. A profile that does
    not requantise may leave ``full_scale_g`` and ``adc_bits`` as None (the
    rate-following reference has no range of its own). ``per_axis`` holds the
    datasheet's figures for the other axes; the profile's own fields are the
    X axis, and :meth:`for_axis` picks another.
    """

    kind: ClassVar[str] = "sensor"
    #: left out of the content hash while unset: existing profiles keep their hashes
    _hash_if_set: ClassVar[frozenset[str]] = frozenset({"per_axis", "stages"})

    sampling_rate_hz: Annotated[float, Field(gt=0)] | Literal["native"] = Field(
        description="Output data rate F_target, Hz; 'native': the recording's own rate."
    )
    full_scale_g: float | None = Field(
        gt=0, description="Full-scale range G_max, g (clip at +/-); None only without requantise."
    )
    adc_bits: int | None = Field(
        ge=1, le=32, description="ADC resolution B, bits; None only without requantise."
    )
    noise_density_ug_rthz: float = Field(ge=0, description="Noise spectral density, ug/sqrt(Hz).")
    inject_noise: bool = Field(
        default=True,
        description="Add white noise from the NSD. False for a chain whose noise the "
        "recording already carries (the reference).",
    )
    requantise: bool = Field(
        default=True,
        description="Apply saturation and quantisation. False for the chain that made the "
        "recording: its ADC already digitised it, a second rounding would alter the data.",
    )
    mech_cutoff_hz: float | None = Field(
        gt=0, description="Mechanical low-pass cutoff f_mech, Hz (None: no mechanical stage)."
    )
    mech_order: int = Field(default=2, ge=1, le=12, description="Mechanical filter order.")
    analog_cutoff_hz: float | None = Field(
        gt=0, description="Analog anti-alias cutoff f_ana, Hz (None: no analog stage)."
    )
    analog_order: int = Field(default=1, ge=1, le=12, description="Anti-alias filter order.")
    digital_cutoff_hz: float | None = Field(
        default=None, gt=0, description="On-chip digital low-pass cutoff f_dig, Hz (None: none)."
    )
    digital_order: int | None = Field(
        default=None, ge=1, le=16, description="On-chip digital low-pass order."
    )
    per_axis: dict[Axis, dict[str, float]] | None = Field(
        default=None,
        description="Per-axis values of noise_density_ug_rthz / mech_cutoff_hz where the "
        "datasheet gives them; the fields above are the X axis.",
    )
    stages: tuple[StageUse, ...] = Field(
        default=(), description="Extra chain stages (plugins), e.g. offset, gauss-markov."
    )
    tolerances: dict[str, Tolerance] = Field(
        default_factory=dict,
        description="Unit-to-unit spread of a numeric field, or of 'stage.parameter' (the "
        "stage is added to a drawn unit if the profile does not list it). Not hashed: the "
        "nominal chain does not depend on it.",
    )

    @field_validator("name")
    @classmethod
    def _check_name(cls, value: str) -> str:
        base = MODE_SUFFIX.sub("", POINT_SUFFIX.sub("", value))
        if not _NAME.match(base):
            raise ValueError(
                f"{value!r} is not a valid name: use lower-case letters, digits, '.', '_' or '-'"
                " (and a part's mode in brackets, e.g. adxl355[range=8g], and a design point's"
                " settings after '~', e.g. adxl345~rate=1600)"
            )
        return value

    @model_validator(mode="after")
    def _check_digital(self) -> SensorSpec:
        if (self.digital_cutoff_hz is None) != (self.digital_order is None):
            raise ValueError("digital_cutoff_hz and digital_order must be given together")
        if self.requantise and (self.full_scale_g is None or self.adc_bits is None):
            raise ValueError("full_scale_g and adc_bits are required when requantise is true")
        if self.sampling_rate_hz == NATIVE:
            if self.digital_cutoff_hz is not None:
                raise ValueError("a sensor at the 'native' rate cannot have a digital filter")
            return self
        nyquist = self.sampling_rate_hz / 2
        if self.digital_cutoff_hz is not None and self.digital_cutoff_hz >= nyquist:
            raise ValueError(
                f"digital_cutoff_hz={self.digital_cutoff_hz:g} Hz is at or above the Nyquist "
                f"frequency {nyquist:g} Hz of sampling_rate_hz={self.sampling_rate_hz:g}; "
                f"lower it below {nyquist:g} Hz or remove the digital filter"
            )
        return self

    @model_validator(mode="after")
    def _check_axes(self) -> SensorSpec:
        for axis, values in (self.per_axis or {}).items():
            if set(values) - set(AXIS_FIELDS) or min(values.values(), default=1) <= 0:
                raise ValueError(f"per_axis.{axis}: only {AXIS_FIELDS}, positive: {values}")
        numeric = {k for k, f in type(self).model_fields.items() if f.annotation in _NUMERIC}
        for key in {k for k in self.tolerances if "." not in k} - numeric:
            raise ValueError(
                f"tolerances.{key}: not a numeric field; use one of {sorted(numeric)} "
                f"or 'stage.parameter'"
            )
        return self

    def at_rate(self, fs: float) -> SensorSpec:
        """This profile for a recording at ``fs`` Hz: a 'native' rate becomes ``fs``."""
        if self.sampling_rate_hz != NATIVE:
            return self
        return self.model_copy(update={"sampling_rate_hz": float(fs)})

    def for_axis(self, axis: str) -> SensorSpec:
        """This profile on ``axis`` ('x', 'y' or 'z'): that axis's datasheet figures, if any."""
        if axis not in ("x", "y", "z"):
            raise ValueError(f"axis must be 'x', 'y' or 'z', got {axis!r}")
        values = (self.per_axis or {}).get(axis) or {}  # type: ignore[call-overload]
        stages = tuple(use.for_axis(axis) for use in self.stages)
        update: dict[str, Any] = {} if stages == self.stages else {"stages": stages}
        if values and {key: getattr(self, key) for key in values} != values:
            update.update(values)
        return self.model_copy(update=update) if update else self

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields (provenance and unset optional fields excluded)."""
        data = super().content_dict()
        data.pop("tolerances", None)  # only drawn units use them, and a unit drops them
        for entry in data.get("stages", ()):
            entry.pop("tolerances", None)
        for key in self._hash_if_set:
            if not data.get(key):
                data.pop(key, None)
        for use, entry in zip(self.stages, data.get("stages", ()), strict=False):
            if use.spec is not None:  # the implementation bound to the name
                entry["impl"] = use.spec.content_hash()
        return data

    @property
    def quantisation_step_g(self) -> float | None:
        """ADC step D = 2 G_max / 2**B, in g (None without a range and resolution)."""
        if self.full_scale_g is None or self.adc_bits is None:
            return None
        return 2.0 * self.full_scale_g / 2.0**self.adc_bits


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
    the sampling rate in Hz and returns (n_windows, len(feature_names)).
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

        ``bands`` is left out: it decides which rates are refused, not the
        values computed. ``dtype`` is left out: ``bytes_per_value`` follows from
        it one to one, so the hash of a float32 set is the one it had before sets
        had a dtype. Both keep feature caches and results folders valid.
        """
        data = super().content_dict()
        data.pop("bands", None)
        data.pop("dtype", None)
        data["compute"] = f"{self.compute.__module__}:{self.compute.__qualname__}"
        return data


class ClassifierSpec(Spec):
    """A scikit-learn-compatible classifier with fixed hyperparameters.

    ``estimator`` is an import path ``"module:Class"``, imported only when an
    estimator is built, so listing classifiers stays fast.
    """

    kind: ClassVar[str] = "classifier"

    estimator: str = Field(description="Import path 'package.module:ClassName'.")
    params: dict[str, Any] = Field(default_factory=dict, description="Hyperparameters.")
    seed_param: str | None = Field(
        default="random_state",
        description="Constructor argument that takes the seed; None if deterministic.",
    )

    @field_validator("estimator")
    @classmethod
    def _check_path(cls, value: str) -> str:
        if not re.match(r"^[A-Za-z_][\w.]*:[A-Za-z_]\w*$", value):
            raise ValueError(f"{value!r} is not an import path of the form 'module:Class'")
        return value

    def estimator_class(self) -> type:
        """Import and return the estimator class."""
        module, _, attr = self.estimator.partition(":")
        try:
            return getattr(importlib.import_module(module), attr)
        except (ImportError, AttributeError) as exc:
            from .errors import SDTError

            raise SDTError(
                f"classifier {self.name!r}: cannot import {self.estimator} ({exc}); "
                f"install the package that provides it"
            ) from exc

    def build(self, seed: int | None = None) -> Any:
        """A fresh, unfitted estimator; ``seed`` goes to ``seed_param`` if set."""
        kwargs = dict(self.params)
        if self.seed_param is not None and seed is not None:
            kwargs[self.seed_param] = seed
        return self.estimator_class()(**kwargs)


class DatasetSpec(Spec):
    """A source of recordings.

    ``loader(path, **options)`` returns a dataset object (see
    ``sdt_framework.data``). ``requires_path`` is False for generated data.
    """

    kind: ClassVar[str] = "dataset"
    _provenance: ClassVar[frozenset[str]] = frozenset({"plugin", "distribution", "loader"})

    loader: Callable[..., Any] = Field(exclude=True, description="loader(path, **options).")
    requires_path: bool = Field(default=True, description="Whether a path must be given.")

    def content_dict(self) -> dict[str, Any]:
        """Behaviour-defining fields plus the loader's qualified name."""
        data = super().content_dict()
        data["loader"] = f"{self.loader.__module__}:{self.loader.__qualname__}"
        return data
