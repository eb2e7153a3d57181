"""What a feature set working in orders of the running speed needs besides the windows.

A set that declares ``needs_speed`` (:class:`~.features.FeatureSetSpec`) has its
``compute(windows, fs, context)`` called with a :class:`FeatureContext`: the
running speed of the recording the windows come from (Hz, and where the figure
comes from: given by the dataset, or read off the spectrum and named an
estimate), its machine (bearings with their defect orders) and its channel.
Its bands are :class:`OrderBand` s, in orders (multiples of the running speed):
at a given speed each is a band in Hz, and the framework refuses a rate whose
Nyquist frequency it passes, naming the band, its order, the speed and where
the rate comes from (:func:`sdt_framework.features.check_order_bands`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel, ConfigDict, Field

from .machine import MachineSpec

__all__ = ["FeatureContext", "OrderBand"]


@dataclass(frozen=True)
class FeatureContext:
    """The recording a batch of windows comes from, as an order-domain feature set needs it.

    Attributes
    ----------
    speed_hz
        Running (shaft) speed, Hz; finite and > 0.
    speed_from
        Where it comes from, for the features' metadata: "given: the archive's
        speed folder", "estimate: 1476 rpm (24.600 Hz) read off the spectrum,
        confidence high: ...".
    machine
        The machine the recording comes from (its bearings), or None.
    channel, recording
        The recording's channel (which bearing sits nearest) and its name (for messages).
    """

    speed_hz: float
    speed_from: str = ""
    machine: MachineSpec | None = None
    channel: str = ""
    recording: str = ""

    def __post_init__(self) -> None:
        if not (isinstance(self.speed_hz, int | float) and math.isfinite(self.speed_hz)):
            raise ValueError(f"speed_hz must be a finite number, got {self.speed_hz!r}")
        if self.speed_hz <= 0:
            raise ValueError(f"speed_hz must be > 0, got {self.speed_hz!r}")

    @property
    def speed_rpm(self) -> float:
        """The running speed, rpm."""
        return self.speed_hz * 60.0

    def describe_speed(self) -> str:
        """``"1480 rpm (24.67 Hz; given: the archive's speed folder)"``."""
        where = f"; {self.speed_from}" if self.speed_from else ""
        return f"{self.speed_rpm:.0f} rpm ({self.speed_hz:.2f} Hz{where})"

    def content(self) -> dict[str, Any]:
        """JSON-ready fields that decide the features (for cache keys)."""
        machine = None
        if self.machine is not None:
            machine = self.machine.model_dump(mode="json", exclude={"origin"})
        return {
            "speed_hz": self.speed_hz,
            "speed_from": self.speed_from,
            "machine": machine,
            "channel": self.channel,
        }


class OrderBand(BaseModel):
    """A band of orders (multiples of the running speed) some features are computed over.

    ``order`` +- ``half_width``, both in orders; ``derivation`` says where the
    order comes from ("3 x BPFI 4.963 of bearing 6309"), for messages. A band
    read off the envelope of the signal above ``carrier_low_hz`` (envelope
    analysis) must also end below the carrier band's width, Nyquist minus that
    edge: the demodulated signal holds no modulation faster than the band is wide.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    name: str = Field(min_length=1, description="The band's name: '1x', 'BPFI x3'.")
    features: tuple[str, ...] = Field(min_length=1, description="Features computed over it.")
    order: float = Field(gt=0, allow_inf_nan=False, description="Centre, orders.")
    half_width: float = Field(gt=0, allow_inf_nan=False, description="Half width, orders.")
    derivation: str = Field(default="", description="Where the order comes from.")
    carrier_low_hz: float | None = Field(
        default=None,
        ge=0,
        allow_inf_nan=False,
        description="For a band of the envelope: the carrier band's lower edge, Hz (to Nyquist).",
    )

    @property
    def low(self) -> float:
        """Lower edge, orders (never below 0)."""
        return max(self.order - self.half_width, 0.0)

    @property
    def high(self) -> float:
        """Upper edge, orders."""
        return self.order + self.half_width

    def edges_hz(self, speed_hz: float) -> tuple[float, float]:
        """The band in Hz at ``speed_hz``: (low, high)."""
        return self.low * speed_hz, self.high * speed_hz

    def describe(self) -> str:
        """``"'BPFI x3' (order 14.89 = 3 x BPFI 4.963 of bearing 6309, +-0.55)"``."""
        why = f" = {self.derivation}" if self.derivation else ""
        return f"{self.name!r} (order {self.order:.4g}{why}, +-{self.half_width:.3g})"
