"""Cross-axis sensitivity: the share of the other two axes' acceleration an axis reads.

The standard linear model of a triaxial accelerometer (IEEE Std 1293-2018,
the misalignment / cross-coupling terms of the model equation) writes the
output of axis i as

    a_out,i = a_i + (c / 100) (a_j + a_k),

with j and k the node's other two axes and c the cross-axis sensitivity in %
of the on-axis sensitivity: the figure datasheets give ("cross-axis
sensitivity +-1 %"). The coupling acts on the sensing element, so the stage
runs first in the chain, on the raw inputs of all three axes (a node stage,
``ctx.node``); a different figure per axis is a ``per_axis`` value and a
unit-to-unit spread a tolerance on ``pct``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from pydantic import BaseModel, ConfigDict, Field

from sdt_framework import SDTError, hookimpl
from sdt_framework.chain import SameRate
from sdt_framework.stages import StageContext, StageSpec

Batch = NDArray[np.float64]

#: what to do when the other axes are missing, quoted in the error
HOW = (
    "map three channels of each run to x, y and z in [benchmark] axes "
    "(e.g. axes = {ch1 = 'x', ch2 = 'y', ch3 = 'z'}), or pass other_axes to degrade()"
)


class CrossAxisParams(BaseModel):
    """Parameters of the cross-axis stage."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    pct: float = Field(
        default=0.0,
        ge=-100,
        le=100,
        description="Cross-axis sensitivity, % of the on-axis sensitivity, from each other axis.",
    )


@dataclass(frozen=True)
class CrossAxis(SameRate):
    """a_out = a + (pct / 100) (a_j + a_k), a_j and a_k the node's other axes (ctx.node)."""

    name: str
    fs_in: float
    gain: float
    sensor: str

    def apply(self, x: Batch, ctx: object) -> Batch:
        """Add the other axes' share to every sample; refuses input without a node."""
        node = getattr(ctx, "node", None)
        if node is None or len(node) != 2:
            raise SDTError(
                f"sensor {self.sensor!r}, stage cross-axis: needs the same acquisitions on the "
                f"node's other two axes; {HOW}"
            )
        if any(other.shape != x.shape for other in node):
            shapes = ", ".join(str(other.shape) for other in node)
            raise SDTError(
                f"sensor {self.sensor!r}, stage cross-axis: the other axes hold {shapes} "
                f"samples, this axis {x.shape}; the three axes of a node must be recorded together"
            )
        return x + self.gain * (node[0] + node[1])


def _cross_axis(params: CrossAxisParams, context: StageContext) -> CrossAxis:
    return CrossAxis(context.label, context.fs, params.pct / 100.0, context.sensor)


STAGES = (
    StageSpec(
        name="cross-axis",
        description="Cross-axis sensitivity of a triaxial node, % from each other axis",
        source="IEEE Std 1293-2018 (linear accelerometer model equation, cross-coupling terms)",
        domain="analog",
        where="before",
        anchor="mechanical",
        node=True,
        params=CrossAxisParams,
        factory=_cross_axis,
        example={"pct": 1.0},
    ),
)


@hookimpl
def register_stages(register):
    """Register cross-axis."""
    for spec in STAGES:
        register(spec)
