"""SensorSpec: every parameter of one sensor's SDT measurement chain (SPEC section 2)."""

from __future__ import annotations

import re
from typing import Annotated, Any, ClassVar, Literal

from pydantic import Field, field_validator, model_validator

from .base import _NAME, Spec
from .stage_use import StageUse, Tolerance
from .supply import Supply

__all__ = ["SensorSpec"]

#: a design point's settings after its base name, e.g. ``adxl345~rate=1600,nsd=90``
#: (a stage parameter's key in full: ``adxl345~gauss-markov.sigma_ug=300``)
POINT_SUFFIX = re.compile(r"~[a-z0-9_.-]+=[a-z0-9.+-]+(,[a-z0-9_.-]+=[a-z0-9.+-]+)*$")
#: a part's operating mode after its name, e.g. ``adxl355[odr=4000,range=8g]``
MODE_SUFFIX = re.compile(r"\[([a-z0-9_]+=[a-z0-9._+-]+)(,[a-z0-9_]+=[a-z0-9._+-]+)*\]$")

#: rate of a sensor that samples at whatever rate the recording has (the identity reference)
NATIVE = "native"
Axis = Literal["x", "y", "z"]
#: how the chain reaches the output rate (docs/chain.md, "Two sampling models")
Sampling = Literal["sample-then-filter", "decimate"]
#: the paper's model (Table 1): every existing profile, and left out of the content hash
PAPER_SAMPLING = "sample-then-filter"
#: SensorSpec fields that may differ per axis (``SensorSpec.per_axis``)
AXIS_FIELDS = ("noise_density_ug_rthz", "mech_cutoff_hz")
#: annotations of the SensorSpec fields a tolerance may apply to
_NUMERIC = (float, float | None, int, int | None)


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
    sampling: Sampling = Field(
        default=PAPER_SAMPLING,
        description="How the output rate is reached. 'sample-then-filter': the paper's model "
        "(Table 1): sample at the output rate with no decimation filter (content above the "
        "output Nyquist folds in), the digital low-pass after. 'decimate': a sigma-delta "
        "part: the digital low-pass is its decimation filter, run at the input rate before "
        "the output rate.",
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
    supply: Supply | None = Field(
        default=None,
        description="Supply current measuring and in standby, turn-on time, each sourced "
        "(sdt_framework.specs.supply). Not hashed: the chain does not depend on it.",
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
        if self.sampling == "decimate" and self.digital_cutoff_hz is None:
            raise ValueError(
                "sampling = 'decimate' needs the decimation low-pass: give digital_cutoff_hz "
                "and digital_order (or use sampling = 'sample-then-filter')"
            )
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
        data.pop("supply", None)  # the node's energy, not the chain
        for entry in data.get("stages", ()):
            entry.pop("tolerances", None)
        for key in self._hash_if_set:
            if not data.get(key):
                data.pop(key, None)
        if data.get("sampling") == PAPER_SAMPLING:  # profiles made before it keep their hash
            data.pop("sampling")
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
