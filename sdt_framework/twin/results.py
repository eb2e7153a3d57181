"""What ``sdt twin check`` finds, typed: the pair read, the alignment, each band and floor.

Every part of a :class:`CheckResult` is a frozen dataclass, so a notebook, the
figure, ``sdt twin fit`` and the command line read ``band.error_db`` rather
than a dict key a typo would miss. :meth:`CheckResult.as_dict` gives the
JSON of ``sdt twin check --json``: the fields in their declared order (the
order of the keys scripts read), sequences as lists, every non-finite float as
None (a THD with no fundamental, a gain of a silent band), the figure's arrays
left out. The calibration's reading is :class:`.verdict.Calibration`, the
samples at full scale :class:`.clipping.Clipping`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, fields, is_dataclass
from typing import Any

import numpy as np

from .clipping import Clipping
from .transfer import Transfer
from .verdict import Calibration, RateSetting, rate_setting

__all__ = [
    "AlignmentInfo",
    "Band",
    "CheckResult",
    "CheckSpectra",
    "DeviceInfo",
    "Distortion",
    "Floor",
    "PairInfo",
    "SideInfo",
    "Summary",
    "plain",
]


@dataclass(frozen=True)
class SideInfo:
    """One side of the pair as read: its channel's label, its part, its rate (Hz)."""

    channel: str
    part: str | None
    rate_hz: float


@dataclass(frozen=True)
class DeviceInfo(SideInfo):
    """The device's side, with the part's nominal output rate (Hz)."""

    nominal_rate_hz: float


@dataclass(frozen=True)
class PairInfo:
    """The pair checked: file, the first 12 hex digits of its SHA-256, the twin's sensor,
    whether that profile was fitted on this file, both sides, the overlap (s), the notes."""

    file: str
    sha256: str
    sensor: str
    in_sample: bool
    reference: SideInfo
    device: DeviceInfo
    overlap_s: float
    notes: tuple[str, ...]


@dataclass(frozen=True)
class AlignmentInfo:
    """The device's measured rate (Hz) and clock error (%), its delay (s), the mounting
    (axis signs, angles in degrees, the rotation applied to the twin) and how well twin and
    device correlate; ``rotation_estimated`` False: no shared motion, axes as mounted."""

    rate_hz: float
    clock_error_pct: float
    delay_s: float
    signs: tuple[int, ...]
    angles_deg: tuple[float, ...]
    rotation: tuple[tuple[float, ...], ...]
    correlation: float
    rotation_estimated: bool


@dataclass(frozen=True)
class Band:
    """One third octave of one axis: edges and centre (Hz), the device's and the twin's RMS
    (g), the twin's error (dB), whether the reference can judge it and why, its transfer."""

    axis: str
    f_lower_hz: float
    f_centre_hz: float
    f_upper_hz: float
    real_rms_g: float
    twin_rms_g: float
    error_db: float
    judgeable: bool
    reason: str
    transfer: Transfer | None


@dataclass(frozen=True)
class Floor:
    """One axis's noise floors (ug/sqrt(Hz)) of reference, twin and device, the twin's
    error (dB), the quiet seconds they were read from (of all), and whether it is judged."""

    axis: str
    reference_ug: float
    twin_ug: float
    device_ug: float
    twin_error_db: float
    quiet_s: float
    of_s: float
    judgeable: bool
    reason: str


@dataclass(frozen=True)
class Distortion:
    """The THD (a share) of the main axis's dominant tone (Hz) on each side."""

    axis: str
    tone_hz: float
    reference: float
    twin: float
    device: float


@dataclass(frozen=True)
class Summary:
    """The judgeable bands, the worst error (dB) with its axis and band, the RMS error (dB)."""

    judgeable_bands: int
    worst_error_db: float
    worst_axis: str
    worst_band_hz: float
    rms_error_db: float


@dataclass(frozen=True, eq=False)
class CheckSpectra:
    """The arrays the figure draws (never in the JSON): densities of device and twin on the
    device's grid ``f`` and of the reference on ``f_ref`` (rows: ``axes``), the main axis,
    the judgeable bands, the transfer ``h`` on ``f_h`` and its coherence."""

    f: np.ndarray
    device: np.ndarray
    twin: np.ndarray
    f_ref: np.ndarray
    reference: np.ndarray
    main: int
    axes: tuple[str, ...]
    judged: tuple[Band, ...]
    f_h: np.ndarray
    h: np.ndarray
    coherence: np.ndarray


@dataclass(frozen=True)
class CheckResult:
    """Everything ``sdt twin check`` prints, JSON-ready through :meth:`as_dict`."""

    pair: PairInfo
    alignment: AlignmentInfo
    bands: tuple[Band, ...]
    floors: tuple[Floor, ...]
    distortion: Distortion
    clipped: Clipping
    calibration: Calibration
    summary: Summary
    spectra: CheckSpectra | None = field(default=None, repr=False, compare=False)

    @property
    def rate_setting(self) -> RateSetting | None:
        """The device's measured rate against the part's nearest output-rate setting."""
        return rate_setting(self.alignment.rate_hz, self.pair.device.nominal_rate_hz)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready form (module docstring): every field but the figure's arrays."""
        return {f.name: plain(getattr(self, f.name)) for f in fields(self) if f.name != "spectra"}


def plain(value: Any) -> Any:
    """``value`` as JSON holds it: dataclasses as dicts in field order, sequences as
    lists, every non-finite float (at any depth) as None."""
    if is_dataclass(value) and not isinstance(value, type):
        return {f.name: plain(getattr(value, f.name)) for f in fields(value)}
    if isinstance(value, Mapping):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [plain(v) for v in value]
    if isinstance(value, float | np.floating) and not np.isfinite(value):
        return None
    return value
