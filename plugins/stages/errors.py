"""Deterministic error stages: offset, scale factor (with their tempcos), nonlinearity.

Each is the standard static model of an accelerometer's transfer function
(IEEE Std 1293-2018, the accelerometer model equation: bias, scale factor and
second/third-order terms), with the temperature coefficients linear about the
profile's reference temperature.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from pydantic import BaseModel, ConfigDict, Field

from sdt_framework import SDTError, hookimpl
from sdt_framework.chain import SameRate
from sdt_framework.stages import StageContext, StageSpec, TemperatureProfile

Batch = NDArray[np.float64]


class OffsetParams(BaseModel):
    """Parameters of the offset stage."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    offset_mg: float = Field(default=0.0, description="Zero-g offset at the reference, mg.")
    tempco_mg_per_c: float = Field(default=0.0, description="Offset tempco, mg per deg C.")
    temperature: TemperatureProfile = Field(default_factory=TemperatureProfile)


class ScaleParams(BaseModel):
    """Parameters of the scale-factor stage."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    error_pct: float = Field(default=0.0, description="Sensitivity error at the reference, %.")
    tempco_pct_per_c: float = Field(default=0.0, description="Sensitivity tempco, % per deg C.")
    temperature: TemperatureProfile = Field(default_factory=TemperatureProfile)


class NonlinearityParams(BaseModel):
    """Parameters of the nonlinearity stage (deviations at full scale, % of full scale)."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    second_pct_fs: float = Field(default=0.0, description="Second-order term at full scale, % FS.")
    third_pct_fs: float = Field(default=0.0, description="Third-order term at full scale, % FS.")
    full_scale_g: float | None = Field(
        default=None, gt=0, description="Full scale, g (default: the sensor's range)."
    )


@dataclass(frozen=True)
class Offset(SameRate):
    """a_out = a + b0 + k_b (T(t) - T_ref): constant offset plus its temperature drift."""

    name: str
    fs_in: float
    params: OffsetParams

    def apply(self, x: Batch, ctx: object) -> Batch:
        """Add the offset (g) at every sample's temperature."""
        delta = self.params.temperature.delta(x.shape[-1], self.fs_in)
        return x + 1e-3 * (self.params.offset_mg + self.params.tempco_mg_per_c * delta)


@dataclass(frozen=True)
class Scale(SameRate):
    """a_out = a (1 + e0 + k_s (T(t) - T_ref)): sensitivity error plus its temperature drift."""

    name: str
    fs_in: float
    params: ScaleParams

    def apply(self, x: Batch, ctx: object) -> Batch:
        """Scale every sample by the sensitivity at its temperature."""
        delta = self.params.temperature.delta(x.shape[-1], self.fs_in)
        p = self.params
        return x * (1.0 + 1e-2 * (p.error_pct + p.tempco_pct_per_c * delta))


@dataclass(frozen=True)
class Nonlinearity(SameRate):
    """a_out = a + k2 a^2 + k3 a^3 with k2 = p2 / (100 FS), k3 = p3 / (100 FS^2).

    p2 and p3 are the second- and third-order deviations at full scale FS in %
    of FS. A tone of amplitude A gains a 2nd harmonic of k2 A^2 / 2 and a 3rd
    of k3 A^3 / 4.
    """

    name: str
    fs_in: float
    k2: float
    k3: float

    def apply(self, x: Batch, ctx: object) -> Batch:
        """Apply the polynomial to every sample."""
        return x + x * x * (self.k2 + self.k3 * x)


def _offset(params: OffsetParams, context: StageContext) -> Offset:
    return Offset(context.label, context.fs, params)


def _scale(params: ScaleParams, context: StageContext) -> Scale:
    return Scale(context.label, context.fs, params)


def _nonlinearity(params: NonlinearityParams, context: StageContext) -> Nonlinearity:
    fs_g = params.full_scale_g or context.full_scale_g
    if fs_g is None:
        raise SDTError(
            f"sensor {context.sensor!r}, stage nonlinearity: the sensor has no range; "
            f"give full_scale_g in the stage's params"
        )
    return Nonlinearity(
        context.label,
        context.fs,
        params.second_pct_fs / (100 * fs_g),
        params.third_pct_fs / (100 * fs_g**2),
    )


SOURCE = "IEEE Std 1293-2018 (linear accelerometer model equation)"
STAGES = (
    StageSpec(
        name="offset",
        description="Zero-g offset and its temperature coefficient",
        source=SOURCE,
        domain="digital",
        where="before",
        anchor="noise",
        params=OffsetParams,
        factory=_offset,
        example={
            "offset_mg": 20,
            "tempco_mg_per_c": 0.5,
            "temperature": {"kind": "ramp", "rate_c_per_s": 1},
        },
    ),
    StageSpec(
        name="scale",
        description="Sensitivity (scale-factor) error and its temperature coefficient",
        source=SOURCE,
        domain="digital",
        where="before",
        anchor="noise",
        params=ScaleParams,
        factory=_scale,
        example={"error_pct": 2, "tempco_pct_per_c": 0.01},
    ),
    StageSpec(
        name="nonlinearity",
        description="Second- and third-order amplitude nonlinearity, % of full scale",
        source=SOURCE,
        domain="analog",
        where="before",
        anchor="sample",
        params=NonlinearityParams,
        factory=_nonlinearity,
        example={"second_pct_fs": 0.5, "third_pct_fs": 0.2},
    ),
)


@hookimpl
def register_stages(register):
    """Register offset, scale and nonlinearity."""
    for spec in STAGES:
        register(spec)
