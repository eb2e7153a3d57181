"""Random error stages: bias instability (Gauss-Markov, 1/f), random walks, white noise.

The models and their Allan-deviation signatures follow IEEE Std 952-1997
(Annex C) and IEEE Std 1293-2018: white noise (velocity random walk) falls as
N / sqrt(tau), bias instability is a floor of sqrt(2 ln 2 / pi) B = 0.664 B,
acceleration random walk rises as K sqrt(tau / 3). Each stage draws from
:func:`sdt_framework.stages.row_normals` (one stream per acquisition, seeded
by the run and the stage's label), only when the run's noise switch is on,
and vectorised over the batch.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from pydantic import BaseModel, ConfigDict, Field

from sdt_framework import hookimpl
from sdt_framework.chain import SameRate
from sdt_framework.stages import StageContext, StageSpec, row_normals
from sdt_framework.units import G_N

Batch = NDArray[np.float64]


class GaussMarkovParams(BaseModel):
    """First-order Gauss-Markov bias: steady-state SD and correlation time."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    sigma_ug: float = Field(gt=0, description="Steady-state standard deviation, ug.")
    tau_s: float = Field(gt=0, description="Correlation time, s.")


class FlickerParams(BaseModel):
    """1/f bias instability B (the Allan floor is 0.664 B)."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    bias_instability_ug: float = Field(gt=0, description="Bias instability B, ug.")


class RandomWalkParams(BaseModel):
    """Acceleration (bias) random walk K."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    k_ug_rts: float = Field(
        gt=0, description="Random walk coefficient K, ug/sqrt(s) (ADEV K sqrt(tau/3))."
    )


class VrwParams(BaseModel):
    """Velocity random walk N, as a datasheet gives it."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    vrw_mps_rthr: float = Field(gt=0, description="Velocity random walk N, (m/s)/sqrt(h).")


class WhiteParams(BaseModel):
    """White noise density (per axis through the profile's per_axis)."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    density_ug_rthz: float = Field(gt=0, description="Noise density, ug/sqrt(Hz).")


@dataclass(frozen=True)
class Additive(SameRate):
    """A random process added to the signal: ``process(z)`` maps draws to g."""

    name: str
    fs_in: float
    kind: str
    a: float
    b: float = 0.0

    def process(self, z: Batch) -> Batch:
        """The process in g from standard normal draws ``z`` (rows x samples)."""
        if self.kind == "white":  # a = per-sample SD
            return self.a * z
        if self.kind == "walk":  # a = K sqrt(dt): a Wiener process sampled at fs
            return np.cumsum(self.a * z, axis=-1)
        if self.kind == "gauss-markov":  # a = sigma, b = phi = exp(-dt / tau)
            from scipy.signal import lfilter  # on first use (plugin discovery stays light)

            u = self.a * np.sqrt(1.0 - self.b**2) * z
            u[:, 0] = self.a * z[:, 0]  # start in the steady state
            return lfilter([1.0], [1.0, -self.b], u, axis=-1)
        return _flicker(z, self.a, self.fs_in)

    def apply(self, x: Batch, ctx) -> Batch:
        """Add the process (nothing if the run's noise is off)."""
        if not ctx.noise:
            return x
        return x + self.process(row_normals(ctx, self.name, x.shape[0], x.shape[-1]))


def _flicker(z: Batch, b_g: float, fs: float) -> Batch:
    """1/f noise of bias instability ``b_g`` (g) by spectral shaping of white draws.

    The one-sided PSD is S(f) = B^2 / (pi f) (IEEE 952's two-sided B^2 / (2 pi f)),
    whose Allan variance is 2 ln 2 B^2 / pi; unit-variance white noise at fs has
    the one-sided PSD 2 / fs, so each bin is scaled by sqrt(S(f) fs / 2). The
    mean (f = 0) is removed.
    """
    n = z.shape[-1]
    f = np.fft.rfftfreq(n, 1.0 / fs)
    gain = np.zeros_like(f)
    gain[1:] = np.sqrt(b_g**2 / (np.pi * f[1:]) * fs / 2.0)
    return np.fft.irfft(np.fft.rfft(z, axis=-1) * gain, n=n, axis=-1)


def _gauss_markov(params: GaussMarkovParams, context: StageContext) -> Additive:
    phi = float(np.exp(-1.0 / (params.tau_s * context.fs)))
    return Additive(context.label, context.fs, "gauss-markov", params.sigma_ug * 1e-6, phi)


def _flicker_stage(params: FlickerParams, context: StageContext) -> Additive:
    return Additive(context.label, context.fs, "flicker", params.bias_instability_ug * 1e-6)


def _walk(params: RandomWalkParams, context: StageContext) -> Additive:
    return Additive(context.label, context.fs, "walk", params.k_ug_rts * 1e-6 / np.sqrt(context.fs))


def _vrw(params: VrwParams, context: StageContext) -> Additive:
    n_g_rts = params.vrw_mps_rthr / 60.0 / G_N  # (m/s)/sqrt(h) -> g sqrt(s): ADEV at 1 s
    return Additive(context.label, context.fs, "white", n_g_rts * np.sqrt(context.fs))


def _white(params: WhiteParams, context: StageContext) -> Additive:
    sd = params.density_ug_rthz * 1e-6 * np.sqrt(context.fs / 2.0)  # as paper eq. 2
    return Additive(context.label, context.fs, "white", sd)


SOURCE = "IEEE Std 952-1997 Annex C; IEEE Std 1293-2018"
_COMMON = {"source": SOURCE, "domain": "digital", "where": "after", "anchor": "noise"}
STAGES = (
    StageSpec(
        name="gauss-markov",
        description="Bias instability as a first-order Gauss-Markov process",
        params=GaussMarkovParams,
        factory=_gauss_markov,
        example={"sigma_ug": 50, "tau_s": 0.1},
        random=True,
        **_COMMON,
    ),
    StageSpec(
        name="flicker",
        description="Bias instability as 1/f (flicker) noise",
        params=FlickerParams,
        factory=_flicker_stage,
        example={"bias_instability_ug": 40},
        random=True,
        **_COMMON,
    ),
    StageSpec(
        name="random-walk",
        description="Acceleration (bias) random walk",
        params=RandomWalkParams,
        factory=_walk,
        example={"k_ug_rts": 10},
        random=True,
        **_COMMON,
    ),
    StageSpec(
        name="vrw",
        description="Velocity random walk: white acceleration noise given as (m/s)/sqrt(h)",
        params=VrwParams,
        factory=_vrw,
        example={"vrw_mps_rthr": 0.05},
        random=True,
        **_COMMON,
    ),
    StageSpec(
        name="white-noise",
        description="Extra white noise density (per axis through per_axis)",
        params=WhiteParams,
        factory=_white,
        example={"density_ug_rthz": 100},
        random=True,
        **_COMMON,
    ),
)


@hookimpl
def register_stages(register):
    """Register the random error stages."""
    for spec in STAGES:
        register(spec)
