"""Sampling-clock error: ODR tolerance and jitter, where the sampler picks its instants.

The sampler of the paper chain takes t_m = m / F. A real ADC's clock runs at
F (1 + e) (the ODR tolerance e) and each instant wanders by a random jitter
j_m (rms ``jitter_s``): t_m = m / (F (1 + e)) + j_m, while the output is still
labelled as F. A tone f0 then appears at f0 / (1 + e); a record of duration
D yields floor(D F (1 + e)) + 1 samples. Linear interpolation between the
recording's samples, as the chain's own sampler (IEEE Std 1241-2010 models
the ADC clock the same way).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from pydantic import BaseModel, ConfigDict, Field

from sdt_framework import hookimpl
from sdt_framework.stages import StageContext, StageSpec, row_normals

Batch = NDArray[np.float64]


class ClockParams(BaseModel):
    """ODR error and jitter of the sampling clock."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    odr_error_pct: float = Field(default=0.0, gt=-50, lt=50, description="ODR error e, %.")
    jitter_s: float = Field(default=0.0, ge=0, description="Sampling jitter, rms seconds.")


@dataclass(frozen=True)
class ClockSampler:
    """Sampling at t_m = m / (F (1 + e)) + jitter, by linear interpolation."""

    name: str
    fs_in: float
    target_hz: float
    odr_error_pct: float
    jitter_s: float

    @property
    def fs_out(self) -> float:
        """The nominal output data rate F (what the sensor reports)."""
        return self.target_hz

    def instants(self, n: int) -> NDArray[np.float64]:
        """Nominal-clock instants of the samples a record of ``n`` input samples yields, s."""
        true_rate = self.target_hz * (1.0 + self.odr_error_pct / 100.0)
        count = int(np.floor((n - 1) / self.fs_in * true_rate + 1e-9)) + 1
        return np.arange(count) / true_rate

    def apply(self, x: Batch, ctx) -> Batch:
        """Interpolate every row at its instants (jitter drawn only when noise is on)."""
        n = x.shape[-1]
        t = self.instants(n)[None, :]
        if self.jitter_s > 0 and ctx.noise:
            t = t + self.jitter_s * row_normals(ctx, self.name, x.shape[0], t.shape[-1])
        u = np.clip(t * self.fs_in, 0.0, n - 1.0)
        j = np.minimum(u.astype(np.intp), n - 2)
        frac = u - j
        if j.shape[0] == 1:
            y0, y1 = x[:, j[0]], x[:, j[0] + 1]
        else:
            y0, y1 = np.take_along_axis(x, j, -1), np.take_along_axis(x, j + 1, -1)
        return y0 + frac * (y1 - y0)


def _clock(params: ClockParams, context: StageContext) -> ClockSampler:
    return ClockSampler(
        context.label,
        context.recording_hz,
        context.target_hz,
        params.odr_error_pct,
        params.jitter_s,
    )


STAGES = (
    StageSpec(
        name="clock",
        description="Sampling-clock ODR error (%) and jitter (rms s), replacing the sampler",
        source="IEEE Std 1241-2010 (ADC clock jitter and frequency error)",
        domain="sampler",
        params=ClockParams,
        factory=_clock,
        example={"odr_error_pct": 1.0, "jitter_s": 1e-6},
        random=True,
    ),
)


@hookimpl
def register_stages(register):
    """Register the clock stage."""
    for spec in STAGES:
        register(spec)
