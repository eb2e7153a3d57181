"""Many sensors on one recording, sharing the stages that run at the recording's rate.

The mechanical and analog low-passes run at F_ref, on the most samples, and
depend only on their own parameters. Sensors (or sweep points, or
repetitions) that differ only in later stages — sampling, noise, digital
filter, quantiser — need them computed once. :class:`SharedPrefix` keeps the
checked recording, runs a prefix once per distinct setting and the rest per
call. Stages treat rows independently and deterministically, so the result is
bit-identical to :func:`~sdt_framework.chain.degrade` on the raw recording.

Memory stays bounded: only the most recent prefix output is kept, so callers
that group their sensors by :func:`prefix_key` compute each prefix once.
"""

from __future__ import annotations

import hashlib
from collections import OrderedDict
from collections.abc import Callable, Mapping

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..specs import SensorSpec
from .chain import Chain, compile_chain
from .checks import check_node, check_signal
from .stages import LowPass, RunContext, Sample, WhiteNoise

__all__ = ["SharedPrefix", "prefix_key", "split_chain"]


def split_chain(chain: Chain) -> tuple[Chain, Chain]:
    """(prefix, rest): the leading recording-rate analog low-passes, and every other stage."""
    count = 0
    for stage in chain.stages:
        if not (isinstance(stage, LowPass) and "digital" not in stage.name):
            break
        count += 1
    return chain.with_stages(chain.stages[:count]), chain.with_stages(chain.stages[count:])


def prefix_key(sensor: SensorSpec, fs: float) -> str:
    """Identifies the prefix of ``sensor``'s chain at ``fs``: equal keys, equal prefix output."""
    prefix, _ = split_chain(compile_chain(sensor, fs))
    digest = hashlib.sha256(repr(fs).encode())
    for stage in prefix.stages:
        digest.update(stage.sos.tobytes())
    return digest.hexdigest()


class SharedPrefix:
    """One recording (a batch of acquisitions at ``fs``) degraded by many sensors.

    Besides the recording-rate prefix, two more results are reused, both
    bit-identical by construction: the sampled signal (the sampling stage's
    output depends only on the prefix output and the target rate) and the
    noise draws (row i's draws depend only on the seed, the acquisition and
    the length: common random numbers), so points that differ only in noise
    density, bits or digital filter share them. A small LRU (``keep``
    entries) bounds the memory; callers that loop over sensors grouped by
    prefix, then repetition, then sensor, reuse each entry while it is held.

    Parameters
    ----------
    x
        1-D acquisition or 2-D batch (acquisitions x samples), in g.
    fs
        Recording rate, Hz.
    label
        The recording's name, quoted in error messages.
    threads
        Worker threads for filtering (as in :func:`~sdt_framework.chain.degrade`).
    keep
        Intermediate arrays held at once.
    other_axes
        The same acquisitions on the triaxial node's other two axes, by axis,
        for a sensor with a node stage (as in ``degrade``).
    """

    def __init__(
        self,
        x: ArrayLike,
        fs: float,
        *,
        label: str = "",
        threads: int = 1,
        keep: int = 6,
        other_axes: Mapping[str, ArrayLike] | None = None,
    ) -> None:
        self.x = x
        self.other_axes = other_axes
        self._node: tuple[NDArray[np.float64], NDArray[np.float64]] | None = None
        self.fs = fs
        self.label = label
        self.threads = threads
        self.keep = keep
        self._checked: NDArray[np.float64] | None = None
        self._held: OrderedDict[tuple, NDArray[np.float64]] = OrderedDict()
        self.prefix_runs = 0

    def _reuse(self, key: tuple, make: Callable[[], NDArray[np.float64]]) -> NDArray[np.float64]:
        if key in self._held:
            self._held.move_to_end(key)
            return self._held[key]
        value = make()
        value.setflags(write=False)  # shared between calls: never written in place
        self._held[key] = value
        while len(self._held) > self.keep:
            self._held.popitem(last=False)
        return value

    def degrade(
        self, sensor: SensorSpec, seed: int = 0, *, noise: bool = True
    ) -> tuple[NDArray[np.float64], float]:
        """Same as ``degrade(x, fs, sensor, seed, noise=noise)``, reusing what it can."""
        if self._checked is None:  # checked once: the samples do not change
            self._checked = check_signal(self.x, sensor, self.label)
        arr = self._checked
        if self.other_axes is not None and self._node is None:
            self._node = check_node(self.other_axes, arr, sensor, self.label)
        chain = compile_chain(sensor, self.fs, label=self.label)
        prefix, rest = split_chain(chain)
        batch = np.atleast_2d(arr)
        ctx = RunContext(
            seed=int(seed),
            acquisition_ids=tuple(range(batch.shape[0])),
            noise=noise,
            threads=max(1, int(self.threads)),
            node=self._node,
        )
        key = prefix_key(sensor, self.fs)

        def run_prefix() -> NDArray[np.float64]:
            self.prefix_runs += 1
            return prefix.run(batch, ctx) if prefix.stages else batch.copy()

        y = self._reuse(("prefix", key), run_prefix)
        stages = list(rest.stages)
        if stages and isinstance(stages[0], Sample):
            sample = stages.pop(0)
            y = self._reuse(("sample", key, sample.target_hz), lambda: sample.apply(y, ctx))
        if stages and isinstance(stages[0], WhiteNoise):
            white = stages.pop(0)
            if noise:
                z = self._reuse(("noise", ctx.seed, y.shape), lambda: white.draws(y.shape, ctx))
                y = y + white.sigma_g * z  # as WhiteNoise.apply
        out = rest.with_stages(stages).run(y, ctx)
        return (out[0] if arr.ndim == 1 else out), chain.fs_out
