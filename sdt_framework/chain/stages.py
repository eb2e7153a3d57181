"""The stages of the measurement chain, each a small object usable on its own.

A stage maps a float64 batch ``(acquisitions, samples)`` at ``fs_in`` to a
batch at ``fs_out`` along the last axis; it never loops over samples, treats
rows independently and returns a new array (never modifies its input), so the
chain may run it on any block of rows, in any thread. Adding a
stage to the chain means writing one more class with ``name``, ``fs_in``,
``fs_out`` and ``apply(x, ctx)`` (the :class:`Stage` protocol) and inserting it
in the tuple :func:`sdt_framework.chain.build_stages` returns.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field, replace
from fractions import Fraction
from functools import lru_cache
from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import NDArray

from ..seeding import rng

__all__ = [
    "LowPass",
    "Quantise",
    "RunContext",
    "SameRate",
    "Sample",
    "Stage",
    "WhiteNoise",
    "sample_count",
    "sample_grid",
]

Batch = NDArray[np.float64]


@dataclass(frozen=True)
class RunContext:
    """What a stage may need beyond the samples: seeds and switches of one call.

    ``acquisition_ids[i]`` names row ``i`` of the batch for seeding, so a row
    gets the same noise whether it is degraded in a batch or alone. ``threads``
    is how many blocks of rows the chain runs at once. ``node`` holds the same
    acquisitions on the triaxial node's other two axes (row ``i`` of each is
    row ``i`` of the batch, at the input rate), for a node stage such as
    cross-axis sensitivity; None when the input is a single axis.
    """

    seed: int = 0
    acquisition_ids: tuple[int | str, ...] = ()
    noise: bool = True
    threads: int = field(default_factory=lambda: len(os.sched_getaffinity(0)))
    node: tuple[Batch, ...] | None = None

    def rows(self, start: int, stop: int) -> RunContext:
        """The context of rows ``start:stop`` of the batch (ids and node rows sliced)."""
        node = None if self.node is None else tuple(a[start:stop] for a in self.node)
        return replace(self, acquisition_ids=self.acquisition_ids[start:stop], node=node)


@runtime_checkable
class Stage(Protocol):
    """One block of the chain: ``apply`` maps a batch at ``fs_in`` to ``fs_out``."""

    name: str
    fs_in: float

    @property
    def fs_out(self) -> float:
        """Rate of the output, Hz."""
        ...

    def apply(self, x: Batch, ctx: RunContext) -> Batch:
        """Process ``x`` (acquisitions x samples) and return the new batch."""
        ...


class SameRate:
    """Mixin of a stage whose output runs at its input's rate: ``fs_out`` is ``fs_in``."""

    fs_in: float

    @property
    def fs_out(self) -> float:
        """Same as ``fs_in``."""
        return self.fs_in


@dataclass(frozen=True)
class LowPass(SameRate):
    """A causal IIR low-pass in SOS form, zero initial conditions (stages 1, 2 and 5)."""

    name: str
    fs_in: float
    sos: NDArray[np.float64] = field(repr=False)

    def apply(self, x: Batch, ctx: RunContext) -> Batch:
        """Filter every row along the last axis."""
        from scipy.signal import sosfilt  # on first use: scipy.signal costs 0.5 s to import

        # sosfilt wants a writable buffer; the cached design stays read-only
        return sosfilt(np.array(self.sos), x, axis=-1)


def sample_count(n: int, fs_in: float, fs_out: float) -> int:
    """M = floor((N - 1) F_target / F_ref) + 1, computed exactly (no float rounding)."""
    return int((n - 1) * Fraction(fs_out) / Fraction(fs_in)) + 1


@lru_cache(maxsize=64)
def sample_grid(
    n: int, fs_in: float, fs_out: float
) -> tuple[
    NDArray[np.intp], NDArray[np.intp], NDArray[np.float64], NDArray[np.float64], NDArray[np.intp]
]:
    """Index arithmetic of the ADC sampling, once per (N, F_ref, F_target).

    Returns ``(j, j1, delta, dx, end)`` such that sample m is
    ``(x[j1] - x[j]) / dx * delta + x[j]``, except at the positions ``end``
    (t_m at or past the last input time) where it is ``x[N-1]``: the same
    operations, in the same order, as ``numpy.interp(m / F_target, n / F_ref,
    x)``, so the result is bit-identical to it.
    """
    t_ref = np.arange(n) / fs_in
    t_out = np.arange(sample_count(n, fs_in, fs_out)) / fs_out
    j = np.clip(np.searchsorted(t_ref, t_out, side="right") - 1, 0, n - 2)
    j1 = j + 1
    delta = t_out - t_ref[j]
    dx = t_ref[j1] - t_ref[j]
    end = np.flatnonzero(t_out >= t_ref[-1])
    for arr in (j, j1, delta, dx, end):
        arr.setflags(write=False)
    return j, j1, delta, dx, end


@dataclass(frozen=True)
class Sample:
    """ADC sampling at ``fs_out`` by linear interpolation, no anti-alias (stage 3)."""

    fs_in: float
    target_hz: float
    name: str = "sample"

    @property
    def fs_out(self) -> float:
        """The sensor's output data rate."""
        return self.target_hz

    def apply(self, x: Batch, ctx: RunContext) -> Batch:
        """Interpolate every row at t_m = m / F_target."""
        j, j1, delta, dx, end = sample_grid(x.shape[-1], self.fs_in, self.target_hz)
        y0 = np.take(x, j, axis=-1)
        out = np.take(x, j1, axis=-1)
        out -= y0  # in place, same operations as (x[j1] - x[j]) / dx * delta + x[j]
        out /= dx
        out *= delta
        out += y0
        out[:, end] = x[:, -1:]
        return out


@dataclass(frozen=True)
class WhiteNoise(SameRate):
    """Additive white Gaussian noise, sigma = NSD sqrt(F/2) (stage 4, paper eq. 2).

    Row i draws from ``seeding.rng(ctx.seed, ctx.acquisition_ids[i])``.
    """

    fs_in: float
    nsd_ug_rthz: float
    name: str = "noise"

    @property
    def sigma_g(self) -> float:
        """Noise standard deviation in g: NSD (ug/sqrt(Hz) -> g/sqrt(Hz)) x sqrt(F/2)."""
        return self.nsd_ug_rthz * 1e-6 * float(np.sqrt(self.fs_in / 2))

    def apply(self, x: Batch, ctx: RunContext) -> Batch:
        """Add the noise of each row's acquisition id (nothing if ``ctx.noise`` is False)."""
        if not ctx.noise:
            return x
        return x + self.sigma_g * self.draws(x.shape, ctx)

    def draws(self, shape: tuple[int, ...], ctx: RunContext) -> Batch:
        """Unit-variance draws of each row: row i from its acquisition id's generator."""
        if len(ctx.acquisition_ids) != shape[0]:
            raise ValueError(f"{len(ctx.acquisition_ids)} acquisition ids for {shape[0]} rows")
        return np.stack([rng(ctx.seed, i).standard_normal(shape[-1]) for i in ctx.acquisition_ids])


@dataclass(frozen=True)
class Quantise(SameRate):
    """Saturation to [-G_max, G_max] then rounding to D = 2 G_max / 2**B (stage 6, eq. 4)."""

    fs_in: float
    full_scale_g: float
    bits: int
    name: str = "quantise"

    @property
    def step_g(self) -> float:
        """Quantisation step D, g."""
        return 2.0 * self.full_scale_g / 2.0**self.bits

    def apply(self, x: Batch, ctx: RunContext) -> Batch:
        """Clip, then x_out = D round(x / D)."""
        step = self.step_g
        return step * np.round(np.clip(x, -self.full_scale_g, self.full_scale_g) / step)
