"""A sensor profile compiled into a chain of stages, and the public ``degrade``.

``build_stages`` turns a :class:`~sdt_framework.specs.SensorSpec` and the
recording's rate into the ordered stages of SPEC section 2 (skipped filters
and an identity resampling left out). ``compile_chain`` caches that per
(profile content, rate) and fuses consecutive low-passes at the same rate into
one SOS cascade: ``sosfilt`` runs each section with the same arithmetic in one
pass or in two, so fusing is bit-identical and halves the passes over 20 kHz data.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field, replace
from functools import lru_cache

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..arguments import check_real, check_seed, check_spec
from ..specs import SensorSpec
from ..stages import build_extra, place, require_bound
from .checks import check_node, check_rates, check_signal
from .filters import design_lowpass
from .stages import LowPass, Quantise, RunContext, Sample, Stage, WhiteNoise

__all__ = ["Chain", "build_stages", "compile_chain", "degrade"]

_BLOCK_VALUES = 1 << 19  # float64 values per block of rows: 4 MB


def build_stages(sensor: SensorSpec, fs: float) -> tuple[Stage, ...]:
    """The stages of ``sensor``'s chain for a recording at ``fs`` Hz, in order.

    With ``sampling = "decimate"`` the digital low-pass runs at ``fs`` as the
    decimation filter, just before the sampling stage; otherwise (the paper's
    model) at the target rate after the noise. Left out: any low-pass whose
    cutoff is None or at or above the Nyquist of
    the rate it runs at (documented skip rule), the sampling stage when the target rate
    equals ``fs`` (interpolating on the same grid is the identity), the
    quantiser when ``sensor.requantise`` is False. The noise stage is kept when
    ``inject_noise`` is True; a call can still switch it off. The profile's
    extra stages (bound to their specs) are placed against these by
    :func:`sdt_framework.stages.place`.
    """
    sensor = sensor.at_rate(fs)
    target = float(sensor.sampling_rate_hz)
    own: dict[str, Stage] = {}
    for name, order, cutoff in (
        ("mechanical", sensor.mech_order, sensor.mech_cutoff_hz),
        ("analog", sensor.analog_order, sensor.analog_cutoff_hz),
    ):
        sos = None if cutoff is None else design_lowpass(order, cutoff, fs)
        if sos is not None:
            own[name] = LowPass(name, fs, sos)
    digital = None
    if sensor.digital_cutoff_hz is not None and sensor.digital_order is not None:
        # the paper's model filters the sampled signal; a decimating (sigma-delta) part
        # filters at the input rate first, so what lies above the output Nyquist is
        # attenuated by the filter's stopband instead of folding into the band
        rate, name = (fs, "decimation") if sensor.sampling == "decimate" else (target, "digital")
        sos = design_lowpass(sensor.digital_order, sensor.digital_cutoff_hz, rate)
        digital = None if sos is None else LowPass(name, rate, sos)
    if digital is not None and digital.name == "decimation":
        own["decimation"] = digital
    if target != fs:
        own["sample"] = Sample(fs, target)
    if sensor.inject_noise and sensor.noise_density_ug_rthz > 0:
        own["noise"] = WhiteNoise(target, sensor.noise_density_ug_rthz)
    if digital is not None and digital.name == "digital":
        own["digital"] = digital
    if sensor.requantise and sensor.full_scale_g is not None and sensor.adc_bits is not None:
        own["quantise"] = Quantise(target, sensor.full_scale_g, sensor.adc_bits)
    if not sensor.stages:
        return tuple(own.values())
    if any(use.spec is None for use in sensor.stages):
        raise ValueError(f"sensor {sensor.name!r}: its stages are not bound; use compile_chain")
    return tuple(place(own, build_extra(sensor, fs)))


def _fuse(stages: Sequence[Stage]) -> tuple[Stage, ...]:
    out: list[Stage] = []
    for stage in stages:
        prev = out[-1] if out else None
        if isinstance(stage, LowPass) and isinstance(prev, LowPass) and prev.fs_in == stage.fs_in:
            sos = np.vstack([prev.sos, stage.sos])
            sos.setflags(write=False)
            out[-1] = LowPass(f"{prev.name}+{stage.name}", stage.fs_in, sos)
        else:
            out.append(stage)
    return tuple(out)


@dataclass(frozen=True)
class Chain:
    """An ordered tuple of stages from ``fs_in`` to ``fs_out`` for one sensor."""

    sensor: SensorSpec
    fs_in: float
    stages: tuple[Stage, ...] = field(default=())

    @property
    def fs_out(self) -> float:
        """Rate of the output: the last stage's, or ``fs_in`` for an empty chain."""
        return self.stages[-1].fs_out if self.stages else self.fs_in

    def with_stages(self, stages: Sequence[Stage]) -> Chain:
        """A copy running ``stages`` instead (to insert, drop or reorder stages)."""
        return replace(self, stages=tuple(stages))

    def run(
        self, x: NDArray[np.float64], ctx: RunContext, *, block_rows: int | None = None
    ) -> NDArray[np.float64]:
        """Apply every stage to a checked float64 batch (acquisitions x samples).

        Rows go through the whole chain in blocks of about 4 MB
        (``block_rows`` rows), ``ctx.threads`` blocks at a time: the 20 kHz
        intermediates stay small and cache-friendly instead of whole-batch
        copies, and ``sosfilt`` and numpy release the GIL. Stages treat rows
        independently, so the result does not depend on blocks or threads.
        The returned array never shares memory with ``x``.
        """
        per = block_rows or max(1, _BLOCK_VALUES // max(1, x.shape[-1]))
        starts = range(0, x.shape[0], per)

        def block(start: int) -> NDArray[np.float64]:
            sub = ctx.rows(start, start + per)
            y = x[start : start + per]
            for stage in self.stages:
                y = stage.apply(y, sub)
            return y

        workers = min(ctx.threads, len(starts))
        if workers < 2:
            parts = [block(start) for start in starts]
        else:
            with ThreadPoolExecutor(workers) as pool:
                parts = list(pool.map(block, starts))
        out = parts[0] if len(parts) == 1 else np.concatenate(parts, axis=0)
        return out.copy() if np.shares_memory(out, x) else out


class _ByContent:
    """Cache key of a sensor: its content hash, carrying the spec along."""

    def __init__(self, sensor: SensorSpec) -> None:
        self.sensor = sensor
        self.key = sensor.content_hash()

    def __hash__(self) -> int:
        return hash(self.key)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, _ByContent) and other.key == self.key


@lru_cache(maxsize=64)
def _compile(keyed: _ByContent, fs: float) -> Chain:
    sensor = keyed.sensor
    return Chain(sensor, fs, _fuse(build_stages(sensor, fs)))


def compile_chain(sensor: SensorSpec, fs: float, *, label: str = "") -> Chain:
    """The chain of ``sensor`` for a recording at ``fs`` Hz, designed once and cached.

    A sensor at the 'native' rate takes ``fs`` as its rate. Raises
    :class:`~sdt_framework.chain.ChainInputError` if the target rate is above
    ``fs`` or the digital cutoff is at or above the target Nyquist; an
    :class:`~sdt_framework.errors.SDTError` if the profile lists stages no
    registry bound (a profile built in Python: ``Registry.bind`` it, or call
    ``sdt_framework.degrade``, which binds it).
    """
    fs = check_rates(fs, sensor, label)
    sensor = require_bound(sensor)
    return _compile(_ByContent(sensor.at_rate(fs)), fs)


def degrade(
    x: ArrayLike,
    fs: float,
    sensor: SensorSpec,
    seed: int = 0,
    *,
    noise: bool = True,
    label: str = "",
    first_index: int = 0,
    acquisition_ids: Sequence[int | str] | None = None,
    threads: int | None = None,
    other_axes: Mapping[str, ArrayLike] | None = None,
) -> tuple[NDArray[np.float64], float]:
    """What ``sensor`` would have recorded of ``x``: the SDT output and its rate.

    Parameters
    ----------
    x
        One acquisition (1-D) or a batch (2-D, acquisitions x samples), in g,
        each row one whole continuous acquisition at ``fs``; real numbers
        (int or float: booleans, complex, objects and text are refused).
    fs
        Recording rate F_ref, Hz (a real number).
    sensor
        The profile; its chain is compiled once per (profile, ``fs``).
        :func:`sdt_framework.api.degrade` also takes a registered name.
    seed
        Base seed, an integer (1.5, "3" or True are refused, not rounded);
        row i's noise comes from ``seeding.rng(seed, id_i)``.
    noise
        False switches the noise stage off for this call.
    label
        The recording's name, quoted in error messages.
    first_index, acquisition_ids
        Noise id of each row: ``acquisition_ids`` if given, else
        ``first_index + i``. Degrading row k alone with ``first_index=k`` is
        bit-identical to row k of the batch.
    threads
        Worker threads for filtering a batch (default: CPUs available).
    other_axes
        For a sensor with a node stage (cross-axis sensitivity): the same
        acquisitions on the triaxial node's other two axes, e.g.
        ``{"y": ay, "z": az}``, each shaped like ``x``. Ignored by other chains.

    Returns
    -------
    (numpy.ndarray, float)
        float64 output with the same number of dimensions as ``x``, and its rate.

    Raises
    ------
    sdt_framework.errors.ArgumentTypeError
        (a TypeError) ``sensor``, ``seed`` or ``fs`` of a wrong type.
    sdt_framework.chain.ChainInputTypeError
        (a TypeError and a ChainInputError) ``x`` not holding real numbers.
    sdt_framework.chain.ChainInputError
        A signal or rate the chain cannot take (shape, NaN, rate below the target).
    """
    sensor = check_spec(SensorSpec, sensor, "sensor")
    seed = check_seed(seed)
    fs = check_real(fs, "fs", "Hz")
    arr = check_signal(x, sensor, label)
    chain = compile_chain(sensor, fs, label=label)
    batch = np.atleast_2d(arr)
    if acquisition_ids is None:
        ids: tuple[int | str, ...] = tuple(range(first_index, first_index + batch.shape[0]))
    else:
        ids = tuple(acquisition_ids)
        if len(ids) != batch.shape[0]:
            raise ValueError(f"{len(ids)} acquisition_ids for {batch.shape[0]} acquisitions")
    node = None if other_axes is None else check_node(other_axes, arr, sensor, label)
    ctx = RunContext(seed=seed, acquisition_ids=ids, noise=noise, node=node)
    if threads is not None:
        ctx = replace(ctx, threads=max(1, int(threads)))
    out = chain.run(batch, ctx)
    return (out[0] if arr.ndim == 1 else out), chain.fs_out
