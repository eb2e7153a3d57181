"""The two signals of a paired recording, and the pair: data only, read by :mod:`.pair`."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

__all__ = ["Pair", "Signal"]


@dataclass(frozen=True)
class Signal:
    """One sensor's recording of the pair: axes on rows, in g, on an even time grid."""

    label: str
    part: str | None
    axes: tuple[str, ...]
    values: np.ndarray  # float64 (n_axes, n_samples)
    rate_hz: float
    start_s: float
    note: str | None = None
    rate_sd_hz: float = float("nan")  # standard error of the measured rate

    @property
    def end_s(self) -> float:
        """Time of the last sample, s."""
        return self.start_s + (self.values.shape[1] - 1) / self.rate_hz


@dataclass(frozen=True)
class Pair:
    """A reference and a device that measured the same vibration on one clock."""

    path: str
    reference: Signal
    device: Signal
    digest: str  # first 12 hex digits of the file's SHA-256 (names the data in provenance)

    @property
    def name(self) -> str:
        """The file's name."""
        return Path(self.path).name
