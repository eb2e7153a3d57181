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
from dataclasses import replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..specs import SensorSpec
from .chain import Chain, compile_chain
from .errors import check_signal
from .stages import LowPass, RunContext

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
    """

    def __init__(self, x: ArrayLike, fs: float, *, label: str = "", threads: int = 1) -> None:
        self.x = x
        self.fs = fs
        self.label = label
        self.threads = threads
        self._checked: NDArray[np.float64] | None = None
        self._key: str | None = None
        self._prefix: NDArray[np.float64] | None = None
        self.prefix_runs = 0

    def degrade(
        self, sensor: SensorSpec, seed: int = 0, *, noise: bool = True
    ) -> tuple[NDArray[np.float64], float]:
        """Same as ``degrade(x, fs, sensor, seed, noise=noise)``, reusing the last prefix."""
        if self._checked is None:  # checked once: the samples do not change
            self._checked = check_signal(self.x, sensor, self.label)
        arr = self._checked
        chain = compile_chain(sensor, self.fs, label=self.label)
        prefix, rest = split_chain(chain)
        batch = np.atleast_2d(arr)
        ctx = RunContext(seed=int(seed), acquisition_ids=tuple(range(batch.shape[0])), noise=noise)
        ctx = replace(ctx, threads=max(1, int(self.threads)))
        key = prefix_key(sensor, self.fs)
        if key != self._key:
            self._prefix = prefix.run(batch, ctx) if prefix.stages else batch
            self._key = key
            self.prefix_runs += 1
        out = rest.run(self._prefix, ctx) if rest.stages else self._prefix.copy()
        return (out[0] if arr.ndim == 1 else out), chain.fs_out
