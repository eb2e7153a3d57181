"""Random draws of a plugin stage, per acquisition, from the run's seed.

Row ``i`` of a batch draws from ``rng(ctx.seed, "stage", label,
ctx.acquisition_ids[i])``: like the chain's white noise it depends on the
run's seed (itself from seed, repetition and recording) and on the
acquisition, never on the sensor's name (common random numbers), and the
stage's label keeps two stages from sharing draws with each other or with the
white noise.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..seeding import rng

__all__ = ["row_normals"]


def row_normals(ctx: Any, label: str, rows: int, n: int) -> NDArray[np.float64]:
    """Standard normal draws, shape (rows, n): one stream per acquisition of ``ctx``.

    Parameters
    ----------
    ctx
        The chain's :class:`~sdt_framework.chain.RunContext` of the batch.
    label
        The stage's label (:attr:`StageContext.label`).
    rows, n
        Rows of the batch (must equal the number of acquisition ids) and draws per row.
    """
    ids = ctx.acquisition_ids
    if len(ids) != rows:
        raise ValueError(f"{len(ids)} acquisition ids for {rows} rows")
    return np.stack([rng(ctx.seed, "stage", label, i).standard_normal(n) for i in ids])
