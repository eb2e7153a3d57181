"""The temperature a sensor sees during an acquisition: constant, a ramp, or a CSV.

Offset and sensitivity drift with temperature through their temperature
coefficients, linear about ``reference_c``. Time runs from 0 at the first
sample of each acquisition (each acquisition is one capture).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Literal

import numpy as np
from numpy.typing import NDArray
from pydantic import BaseModel, ConfigDict, Field, model_validator

from ..errors import SDTError

__all__ = ["TemperatureProfile"]


@lru_cache(maxsize=16)
def _read_csv(path: str) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    try:
        table = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    except (OSError, ValueError) as exc:
        raise SDTError(
            f"temperature profile {path!r}: {exc}; give a CSV with a header line and "
            f"columns time_s,temperature_c"
        ) from None
    if table.shape[1] != 2 or len(table) < 1 or np.any(np.diff(table[:, 0]) <= 0):
        raise SDTError(
            f"temperature profile {path!r}: need two columns time_s,temperature_c with "
            f"strictly increasing times"
        )
    return table[:, 0], table[:, 1]


class TemperatureProfile(BaseModel):
    """Temperature against time within an acquisition.

    ``constant``: ``celsius`` throughout; ``ramp``: ``celsius + rate_c_per_s
    * t``; ``csv``: linear interpolation of the file's (time_s, temperature_c)
    rows, held at the first and last value outside them.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    kind: Literal["constant", "ramp", "csv"] = Field(default="constant", description="Profile.")
    celsius: float = Field(default=25.0, description="Temperature (start of a ramp), deg C.")
    rate_c_per_s: float = Field(default=0.0, description="Ramp slope, deg C per second.")
    path: str | None = Field(default=None, description="CSV of time_s,temperature_c (csv).")
    reference_c: float = Field(default=25.0, description="Temperature of the nominal values.")

    @model_validator(mode="after")
    def _check(self) -> TemperatureProfile:
        if (self.kind == "csv") != (self.path is not None):
            raise ValueError("path is required for kind='csv' and only for it")
        return self

    def delta(self, n: int, fs: float) -> NDArray[np.float64] | float:
        """T(t) - reference_c at t = k / fs, k < n (a float when constant), deg C."""
        if self.kind == "constant":
            return self.celsius - self.reference_c
        t = np.arange(n) / fs
        if self.kind == "ramp":
            return self.celsius + self.rate_c_per_s * t - self.reference_c
        times, temps = _read_csv(str(self.path))
        return np.interp(t, times, temps) - self.reference_c
